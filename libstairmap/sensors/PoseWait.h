#pragma once
// Scans waiting for their robot pose. Poses come from a trajectory that is still growing (a pose
// estimator writes it while the sensor streams), so a scan newer than the last pose waits, for a
// bounded time, then is given up and counted. Scans leave in arrival order (the mapper wants
// increasing time), so a waiting scan holds back the ones behind it. Not thread-safe.

#include <cstddef>
#include <deque>
#include <vector>

#include "core/Scan.h"
#include "io/rawlog/TumTrajectory.h"

namespace stairmap::sensors {

struct PoseWaitParams {
    double max_wait_s = 0.5;       ///< [s] a scan waits at most this long (arrival clock) for its pose
    double tolerance_s = 0.05;     ///< [s] allowed extrapolation beyond the trajectory's ends
    std::size_t max_pending = 64;  ///< [-] more waiting scans than this: the oldest is given up
};

class PoseWait {
public:
    explicit PoseWait(const PoseWaitParams& params = {}) : params_(params) {}

    /// Queues a scan (Scan::stamp_s is looked up) that arrived at `arrival_s` [s, any clock that
    /// release() uses too].
    void add(Scan scan, double arrival_s);

    /// Scans whose pose is now known, oldest first, with T_world_robot set. Scans that waited
    /// longer than max_wait_s, or are older than the trajectory's start (their pose will never
    /// come), are dropped and counted in withoutPose().
    std::vector<Scan> release(const io::TumTrajectory& poses, double now_s);

    std::size_t pending() const { return queue_.size(); }
    std::size_t withoutPose() const { return without_pose_; }

private:
    struct Waiting {
        Scan scan;
        double arrival_s;
    };
    PoseWaitParams params_;
    std::deque<Waiting> queue_;
    std::size_t without_pose_ = 0;
};

}  // namespace stairmap::sensors
