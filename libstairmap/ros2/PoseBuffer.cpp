#include "ros2/PoseBuffer.h"

#include <algorithm>
#include <cmath>

namespace stairmap::ros2 {

bool PoseBuffer::add(double stamp_s, const Eigen::Isometry3d& T_world_robot) {
    if (!std::isfinite(stamp_s) || !T_world_robot.matrix().allFinite()) return false;
    if (!poses_.empty() && stamp_s <= poses_.back().stamp_s) return false;
    poses_.push_back({stamp_s, T_world_robot.translation(), Eigen::Quaterniond(T_world_robot.rotation())});
    while (poses_.size() > params_.max_poses ||
           (poses_.size() > 2 && poses_.front().stamp_s < stamp_s - params_.keep_s))
        poses_.pop_front();
    return true;
}

PoseLookup PoseBuffer::lookup(double stamp_s, Eigen::Isometry3d& T_world_robot) const {
    if (poses_.empty() || stamp_s > poses_.back().stamp_s + params_.tolerance_s) return PoseLookup::NotYet;
    if (stamp_s < poses_.front().stamp_s - params_.tolerance_s) return PoseLookup::TooOld;
    auto make = [&](const Eigen::Vector3d& t, const Eigen::Quaterniond& q) {
        T_world_robot = Eigen::Isometry3d::Identity();
        T_world_robot.linear() = q.normalized().toRotationMatrix();
        T_world_robot.translation() = t;
        return PoseLookup::Found;
    };
    if (stamp_s >= poses_.back().stamp_s) return make(poses_.back().t, poses_.back().q);
    if (stamp_s <= poses_.front().stamp_s) return make(poses_.front().t, poses_.front().q);
    // first pose later than the stamp; the one before it is at or before the stamp
    const auto after = std::upper_bound(poses_.begin(), poses_.end(), stamp_s,
                                        [](double t, const Stamped& p) { return t < p.stamp_s; });
    const Stamped& b = *after;
    const Stamped& a = *(after - 1);
    const double span = b.stamp_s - a.stamp_s;
    if (span > params_.max_gap_s) return PoseLookup::Gap;
    const double u = (stamp_s - a.stamp_s) / span;
    return make(a.t + u * (b.t - a.t), a.q.slerp(u, b.q));
}

}  // namespace stairmap::ros2
