#pragma once
// The contract between live scan sources (a followed rawlog, MRPT sensor drivers, ROS 2 topics) and
// the live mapping runner, and between the runner and whoever publishes the landmarks it keeps.
// Sources push scans as they arrive; the runner owns the bounded queue and the mapping thread, so a
// source never waits for the detector (issue 11, "Under load").

#include <atomic>
#include <cstddef>
#include <map>
#include <string>

#include "core/Scan.h"
#include "map/LandmarkMap.h"

namespace stairmap::live {

/// Where a source hands its scans. Thread-safe: a source may push from its own threads
/// (a DDS listener, a driver thread).
class ScanSink {
public:
    virtual ~ScanSink() = default;
    /// Hands one scan (robot frame, with its pose) to the mapper. Lossy sources: never blocks; when
    /// the queue is full the oldest queued scan is dropped and counted. Lossless sources (files):
    /// blocks until there is room or a stop is requested.
    virtual void push(Scan scan) = 0;
};

/// A live stream of scans. run() is called once, on a thread of its own.
class LiveSource {
public:
    virtual ~LiveSource() = default;
    /// Streams scans into `sink` until the stream ends (returns) or `stop` becomes true (returns
    /// soon after, within ~0.2 s). Throws std::runtime_error naming the source on a fatal error
    /// (e.g. the file vanished); bad single messages are counted, never thrown.
    virtual void run(ScanSink& sink, const std::atomic<bool>& stop) = 0;
    /// true for streams that cannot wait (sensor, ROS 2): the runner drops the oldest scans when
    /// it falls behind. false for files: the reader falls behind instead, nothing is dropped.
    virtual bool lossy() const = 0;
    /// One line naming the source, e.g. "rawlog /data/run.rawlog (followed)".
    virtual std::string describe() const = 0;
    /// The source's own counters for stats.json and the status line (e.g. "clouds_without_xyz",
    /// "scans_without_pose", "malformed_messages"). Thread-safe; a snapshot.
    virtual std::map<std::string, std::size_t> counters() const = 0;
};

/// Told about every change of the landmark map (on the mapping thread, after the change), and once
/// at the start with the map loaded by --map-in. E.g. the ROS 2 MarkerArray/staircase publisher.
class LandmarkListener {
public:
    virtual ~LandmarkListener() = default;
    /// stamp_s: stamp of the scan whose processing caused the change [s].
    virtual void onLandmarks(const LandmarkMap& landmarks, double stamp_s) = 0;
};

}  // namespace stairmap::live
