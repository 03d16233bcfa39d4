#include "sensors/PoseWait.h"

namespace stairmap::sensors {

void PoseWait::add(Scan scan, double arrival_s) {
    queue_.push_back({std::move(scan), arrival_s});
    while (queue_.size() > params_.max_pending) {
        queue_.pop_front();
        ++without_pose_;
    }
}

std::vector<Scan> PoseWait::release(const io::TumTrajectory& poses, double now_s) {
    std::vector<Scan> ready;
    while (!queue_.empty()) {
        Waiting& head = queue_.front();
        const double t = head.scan.stamp_s;
        // Within the trajectory's span the pose is final. Past its end a later pose may still be
        // written: wait for it, and only when the wait is over accept the end pose within the
        // tolerance (rather than take the end pose at once for a scan slightly newer than it).
        const bool within = !poses.empty() && t <= poses.poses().back().stamp_s;
        const bool waited_out = now_s - head.arrival_s > params_.max_wait_s;
        if (!within && !waited_out) break;  // keep the order: the ones behind wait too
        if (const auto T = poses.poseAt(t, params_.tolerance_s)) {
            head.scan.T_world_robot = *T;
            ready.push_back(std::move(head.scan));
        } else {
            ++without_pose_;  // older than the trajectory, or its pose never came
        }
        queue_.pop_front();
    }
    return ready;
}

}  // namespace stairmap::sensors
