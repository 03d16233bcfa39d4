#pragma once
// Pairs scans with robot poses that arrive as separate stream entries (CObservationRobotPose in a
// rawlog, in either order relative to the scan), in constant memory.
//
// Rule: a scan's pose is the recorded pose NEAREST in time to the scan, if within tolerance_s.
// A scan waits (FIFO) until its pose is certain: a pose with exactly its timestamp (|dt| < 1 us)
// has been seen, or the stream time has passed scan time + tolerance_s, or more than
// max_pending scans wait, or the stream ended. Scans leave in the order they came.
// Cost: O(poses kept) per resolution; at most max_poses_kept poses are kept.

#include <Eigen/Geometry>
#include <cstddef>
#include <deque>
#include <optional>

#include "core/Scan.h"

namespace stairmap::io {

struct RobotPoseMatcherParams {
    double tolerance_s = 0.05;         ///< [s] max |t_pose - t_scan| to use a pose
    std::size_t max_pending = 16;      ///< scans waiting for a pose before forced resolution
    std::size_t max_poses_kept = 256;  ///< recent poses remembered
};

/// A scan waiting for its pose, with an optional fallback (e.g. composed odometry).
struct PendingScan {
    Scan scan;
    std::optional<Eigen::Isometry3d> fallback_T_world_robot;  ///< used when no pose matches
};

class RobotPoseMatcher {
public:
    explicit RobotPoseMatcher(const RobotPoseMatcherParams& params = {});

    void addPose(double stamp_s, const Eigen::Isometry3d& T_world_robot);
    void addScan(PendingScan scan);
    /// Latest timestamp seen on the stream (any entry), lets waiting scans resolve.
    void observeStreamTime(double stamp_s);

    /// Next resolved scan in FIFO order, if any is ready. `scan` set: pose found (or fallback);
    /// `scan` empty with `resolved` true: no pose, the scan is dropped. `final` = stream ended.
    struct Resolution {
        bool resolved = false;
        std::optional<Scan> scan;
    };
    Resolution pop(bool final);

    bool anyPoseSeen() const { return any_pose_seen_; }
    bool hasPending() const { return !pending_.empty(); }

private:
    bool frontIsReady(bool final) const;
    std::optional<Eigen::Isometry3d> nearestPose(double t) const;

    RobotPoseMatcherParams params_;
    std::deque<PendingScan> pending_;
    std::deque<std::pair<double, Eigen::Isometry3d>> poses_;
    std::optional<double> latest_stream_time_;
    bool any_pose_seen_ = false;
};

}  // namespace stairmap::io
