#include "io/rawlog/RobotPoseMatcher.h"

#include <cmath>

namespace stairmap::io {
namespace {
constexpr double kExactMatch_s = 1e-6;
}

RobotPoseMatcher::RobotPoseMatcher(const RobotPoseMatcherParams& params) : params_(params) {}

void RobotPoseMatcher::addPose(double stamp_s, const Eigen::Isometry3d& T_world_robot) {
    any_pose_seen_ = true;
    poses_.emplace_back(stamp_s, T_world_robot);
    while (poses_.size() > params_.max_poses_kept) poses_.pop_front();
    observeStreamTime(stamp_s);
}

void RobotPoseMatcher::addScan(PendingScan scan) {
    const double t = scan.scan.stamp_s;
    pending_.push_back(std::move(scan));
    observeStreamTime(t);
}

void RobotPoseMatcher::observeStreamTime(double stamp_s) {
    if (!std::isfinite(stamp_s)) return;
    if (!latest_stream_time_ || stamp_s > *latest_stream_time_) latest_stream_time_ = stamp_s;
}

std::optional<Eigen::Isometry3d> RobotPoseMatcher::nearestPose(double t) const {
    const std::pair<double, Eigen::Isometry3d>* best = nullptr;
    for (const auto& p : poses_) {
        if (!best || std::abs(p.first - t) < std::abs(best->first - t)) best = &p;
    }
    if (!best || !(std::abs(best->first - t) <= params_.tolerance_s)) return std::nullopt;
    return best->second;
}

bool RobotPoseMatcher::frontIsReady(bool final) const {
    if (pending_.empty()) return false;
    if (final || pending_.size() > params_.max_pending) return true;
    const double t = pending_.front().scan.stamp_s;
    if (latest_stream_time_ && *latest_stream_time_ > t + params_.tolerance_s) return true;
    for (const auto& p : poses_) {
        if (std::abs(p.first - t) < kExactMatch_s) return true;
    }
    return false;
}

RobotPoseMatcher::Resolution RobotPoseMatcher::pop(bool final) {
    Resolution r;
    if (!frontIsReady(final)) return r;
    PendingScan p = std::move(pending_.front());
    pending_.pop_front();
    r.resolved = true;
    // Once the stream carries absolute poses, odometry is never mixed in (different origins).
    std::optional<Eigen::Isometry3d> T = nearestPose(p.scan.stamp_s);
    if (!T && !any_pose_seen_) T = p.fallback_T_world_robot;
    if (T) {
        p.scan.T_world_robot = *T;
        r.scan = std::move(p.scan);
    }
    return r;
}

}  // namespace stairmap::io
