#pragma once
// The live mapping runner: a source on a thread of its own pushes scans into a bounded ScanQueue;
// the calling thread is the one mapping thread and runs the same pipeline::Mapper as `stairmap
// map` on each scan. Landmark listeners hear of every change (and once at the start); a tick
// callback runs about every tick_period_s on the mapping thread (status line, stats.json,
// snapshots), so the mapper is only ever touched by one thread.
//
// Latency: each scan's arrival is stamped when it is pushed. For every scan the runner records
// the queue wait (arrival -> taken by the mapper), the processing time (Mapper::processScan) and
// their sum; for a scan whose processing changed the landmark map, arrival -> end of that
// processScan (listeners included) is the update latency the issue asks for. All four are kept in
// fixed memory (LatencyStats), so memory stays flat over any stream length.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "live/LatencyStats.h"
#include "live/LiveSource.h"
#include "live/ScanQueue.h"
#include "pipeline/Mapper.h"

namespace stairmap::live {

struct LiveRunnerParams {
    std::size_t queue_capacity = 4;  ///< [scans] input queue bound (ScanQueueParams::capacity)
    double duration_s = 0.0;         ///< [s] wall time after which the run ends; 0 = no limit
    std::size_t max_scans = 0;       ///< scans mapped after which the run ends; 0 = no limit
    double tick_period_s = 1.0;      ///< [s] period of the tick callback
    double poll_period_s = 0.05;     ///< [s] stop checks while no scan arrives
};

/// Why a run ended.
enum class LiveEnd { SourceEnded, StopRequested, Duration, MaxScans };
const char* toString(LiveEnd end);

/// A snapshot of the run (mapping thread).
struct LiveStatus {
    double elapsed_s = 0.0;          ///< [s] wall time since run() started
    std::size_t scans_mapped = 0;    ///< scans processed by the mapper
    double scans_per_s = 0.0;        ///< over the last tick period
    double lag_s = 0.0;              ///< [s] newest scan pushed minus last scan mapped (stamps)
    double last_stamp_s = 0.0;       ///< [s] stamp of the last scan mapped
    std::size_t landmark_changes = 0;
    std::size_t staircases = 0;
    ScanQueueCounters queue;
    LatencySummary update_latency;   ///< arrival -> end of the processScan that changed landmarks
    LatencySummary scan_latency;     ///< arrival -> end of processScan, every scan
    LatencySummary processing;       ///< processScan alone
    LatencySummary queue_wait;       ///< arrival -> taken from the queue
    std::map<std::string, std::size_t> source_counters;
    bool lossy = false;
};

class LiveRunner {
public:
    /// `mapper` and `source` must outlive the runner. The runner installs the mapper's
    /// landmarks-changed callback.
    LiveRunner(pipeline::Mapper& mapper, LiveSource& source, const LiveRunnerParams& params);
    ~LiveRunner();
    LiveRunner(const LiveRunner&) = delete;
    LiveRunner& operator=(const LiveRunner&) = delete;

    /// Told about every landmark change and once at the start. Must outlive run().
    void addListener(LandmarkListener& listener);
    /// Called on the mapping thread about every tick_period_s, and once at the end.
    void setTickCallback(std::function<void(const LiveStatus&)> tick);
    /// Polled on the mapping thread after each scan and every poll_period_s; true ends the run
    /// after the scan in hand (e.g. SIGINT).
    void setStopCheck(std::function<bool()> check);

    /// Runs until the source ends and every scan it pushed is mapped, a stop, --duration or
    /// --max-scans. Queued scans left at a stop are not mapped. Call once. An exception from the
    /// mapper, a listener or the tick callback stops and joins the source, then propagates.
    LiveEnd run();

    LiveStatus status() const;
    /// The source's fatal error (it threw), if any; the run then ended as SourceEnded.
    const std::optional<std::string>& sourceError() const { return source_error_; }

private:
    std::optional<LiveEnd> limitReached() const;
    LiveEnd mapUntilEnd(std::chrono::milliseconds poll);
    void mapOne(QueuedScan item);
    void tickIfDue(bool force);
    void sourceThread();

    using Clock = std::chrono::steady_clock;
    pipeline::Mapper& mapper_;
    LiveSource& source_;
    LiveRunnerParams params_;
    std::atomic<bool> stop_{false};
    ScanQueue queue_;
    std::vector<LandmarkListener*> listeners_;
    std::function<void(const LiveStatus&)> tick_;
    std::function<bool()> stop_check_;
    std::optional<std::string> source_error_;
    std::mutex error_mutex_;
    Clock::time_point start_{}, last_tick_{};
    std::size_t scans_at_last_tick_ = 0;
    double rate_ = 0.0;
    double current_stamp_s_ = 0.0;
    double last_stamp_s_ = 0.0;
    bool changed_ = false;
    std::size_t landmark_changes_ = 0;
    LatencyStats update_latency_, scan_latency_, processing_, queue_wait_;
};

}  // namespace stairmap::live
