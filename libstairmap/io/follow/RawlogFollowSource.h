#pragma once
// `stairmap live --follow FILE.rawlog`: a plain rawlog still being written, as a live source.
// The file is read through a GrowingFileStream by the same RawlogScanSource that `stairmap map`
// uses (both rawlog formats, every observation type, CObservationRobotPose / odometry poses,
// guarded object reads), so the scans and poses are the ones `map` would give for the finished
// file. Poses: a TUM file that may itself be growing (GrowingTrajectory), or a static robot, or
// what the rawlog carries. Lossless: the runner never drops a followed file's scans; when the
// mapper is slow, this reader waits and falls behind the file (bytes_behind says how far).
// The run ends when the file has not grown for idle_timeout_s, or at a stop.

#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <string>

#include "io/follow/GrowingFileStream.h"
#include "io/follow/GrowingTrajectory.h"
#include "io/rawlog/RawlogScanSource.h"
#include "live/LiveSource.h"

namespace stairmap::io {

struct RawlogFollowParams {
    GrowingFileParams file;           ///< idle timeout of the followed rawlog
    RawlogSourceParams rawlog;        ///< label filter, pose tolerances, object size cap
    std::string poses_path;           ///< growing TUM file; empty: poses from the rawlog
    GrowingTrajectoryParams poses;    ///< how long a scan waits for its pose, etc.
    bool static_robot = false;        ///< identity pose for every scan (excludes poses_path)
    /// Told each reader warning as it happens (unsupported type, first pose-less scan, ...), on
    /// the source's thread. Optional.
    std::function<void(const std::string&)> on_warning;
};

/// Checks, without waiting, that `path` can be followed: an existing, readable, plain (not gzip)
/// file whose first bytes, if any, start an MRPT serialized object. Throws std::runtime_error
/// "<path>: ..." saying what is wrong. An empty file is accepted (its writer has not started).
void checkFollowableRawlog(const std::string& path);

class RawlogFollowSource : public live::LiveSource {
public:
    /// Nothing is opened until run(); call checkFollowableRawlog first for early errors.
    RawlogFollowSource(std::string path, RawlogFollowParams params);

    /// Reads until the file stops growing (idle timeout) or `stop`. Throws std::runtime_error
    /// naming the file when it is corrupt, ends inside an object, shrinks, or the TUM file has a
    /// malformed line; the scans before are pushed first.
    void run(live::ScanSink& sink, const std::atomic<bool>& stop) override;
    bool lossy() const override { return false; }
    std::string describe() const override;
    /// objects_read, scans_read, scans_pushed, skipped_no_pose, skipped_label,
    /// conversion_failed, robot_poses_read, odometry_read, non_finite_dropped, unsupported,
    /// bytes_read, bytes_behind, tum_poses_read, scans_waited_for_pose.
    std::map<std::string, std::size_t> counters() const override;
    /// Warnings of the rawlog reader so far (unsupported types, first pose-less scan, ...).
    std::vector<std::string> messages() const;

private:
    RawlogScanSource::PoseLookup poseLookup(const std::atomic<bool>& stop);
    void snapshot(const RawlogScanSource& source, const GrowingFileStream& stream);
    [[noreturn]] void fail(const std::string& error, const GrowingFileStream& stream) const;

    std::string path_;
    RawlogFollowParams params_;
    std::unique_ptr<GrowingTrajectory> trajectory_;
    mutable std::mutex mutex_;
    std::map<std::string, std::size_t> counters_;
    std::vector<std::string> messages_;
};

}  // namespace stairmap::io
