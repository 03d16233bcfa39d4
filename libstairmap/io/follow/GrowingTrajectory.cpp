#include "io/follow/GrowingTrajectory.h"

#include <thread>

namespace stairmap::io {

GrowingTrajectory::GrowingTrajectory(const std::string& path,
                                     const GrowingTrajectoryParams& params,
                                     const std::atomic<bool>& stop)
    : tum_(path), params_(params), stop_(stop) {
    last_growth_ = std::chrono::steady_clock::now();
    tum_.refresh();
}

std::optional<Eigen::Isometry3d> GrowingTrajectory::poseAt(double t) {
    bool waited = false;
    for (;;) {
        const TumTrajectory& poses = tum_.trajectory();
        const bool covered = !poses.empty() && poses.poses().back().stamp_s >= t;
        if (covered || stop_.load()) break;
        if (tum_.refresh()) {
            last_growth_ = std::chrono::steady_clock::now();
            continue;
        }
        const auto idle = std::chrono::steady_clock::now() - last_growth_;
        if (std::chrono::duration<double>(idle).count() >= params_.wait_s) break;
        waited = true;
        std::this_thread::sleep_for(std::chrono::duration<double>(params_.poll_period_s));
    }
    if (waited) ++waits_;
    tum_.forgetBefore(t - params_.keep_s);
    return tum_.trajectory().poseAt(t, params_.tolerance_s);
}

}  // namespace stairmap::io
