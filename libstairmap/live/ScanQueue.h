#pragma once
// The bounded queue between a live source and the mapping thread (issue 11, "Under load").
// A source pushes from its own thread; the mapping thread pops. Memory is bounded by `capacity`
// scans whatever the source does:
//   lossy (sensor, ROS 2): push never blocks; when full, the OLDEST queued scan is dropped and
//     counted, so the mapper always works on the freshest data;
//   lossless (a followed file): push blocks until there is room or a stop is requested, so the
//     reader falls behind the file instead of losing scans.
// Each scan's arrival time (steady clock) is recorded at push, for the latency figures.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

#include "live/LiveSource.h"

namespace stairmap::live {

struct ScanQueueParams {
    std::size_t capacity = 4;  ///< [scans] queued at most (>= 1); ~0.4 s of a 10 Hz LiDAR
    bool lossy = false;        ///< drop the oldest when full (true) or block the pusher (false)
};

/// A scan with the time it reached the queue.
struct QueuedScan {
    Scan scan;
    std::chrono::steady_clock::time_point arrival;
};

/// Counters of the queue; a consistent snapshot.
struct ScanQueueCounters {
    std::size_t pushed = 0;             ///< scans handed to push()
    std::size_t dropped = 0;            ///< lossy: oldest scans dropped because the queue was full
    std::size_t discarded_on_stop = 0;  ///< lossless: pushes abandoned because a stop came first
    std::size_t queued = 0;             ///< waiting now
    std::size_t peak_queued = 0;        ///< most ever waiting
    double newest_stamp_s = 0.0;        ///< [s] stamp of the last scan pushed (0 before any)
};

class ScanQueue : public ScanSink {
public:
    /// `stop` ends blocking pushes (lossless) within ~0.1 s. Throws std::invalid_argument if
    /// capacity is 0.
    ScanQueue(const ScanQueueParams& params, const std::atomic<bool>& stop);

    void push(Scan scan) override;

    /// The oldest queued scan, waiting up to `wait` for one. std::nullopt on timeout, or at once
    /// when the queue is closed and empty.
    std::optional<QueuedScan> pop(std::chrono::milliseconds wait);
    /// The source is done: no more pushes; pop() returns what is queued, then std::nullopt.
    void close();
    /// True once closed and empty (every scan the source pushed has been popped).
    bool drained() const;
    /// Wakes a pusher blocked on a full queue (call after setting the stop flag).
    void wake();

    ScanQueueCounters counters() const;
    const ScanQueueParams& params() const { return params_; }

private:
    ScanQueueParams params_;
    const std::atomic<bool>& stop_;
    mutable std::mutex mutex_;
    std::condition_variable not_empty_, not_full_;
    std::deque<QueuedScan> queue_;
    ScanQueueCounters counters_;
    bool closed_ = false;
};

}  // namespace stairmap::live
