#include "io/follow/GrowingTrajectory.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace stairmap::io {

GrowingTrajectory::GrowingTrajectory(const std::string& path,
                                     const GrowingTrajectoryParams& params,
                                     const std::atomic<bool>& stop)
    : path_(path), params_(params), stop_(stop) {
    if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open TUM trajectory file");
    last_growth_ = std::chrono::steady_clock::now();
    refresh();
}

bool GrowingTrajectory::refresh() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw std::runtime_error(path_ + ": TUM trajectory file vanished while followed");
    in.seekg(static_cast<std::streamoff>(offset_));
    std::string tail((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto last_newline = tail.rfind('\n');
    if (last_newline == std::string::npos) return false;  // no complete new line yet
    const std::string complete = tail.substr(0, last_newline + 1);
    offset_ += complete.size();
    std::istringstream lines(complete);
    const std::string name = path_ + " (lines after " + std::to_string(lines_) + ")";
    lines_ += static_cast<std::size_t>(std::count(complete.begin(), complete.end(), '\n'));
    append(TumTrajectory::read(lines, name));
    last_growth_ = std::chrono::steady_clock::now();
    return true;
}

void GrowingTrajectory::append(const TumTrajectory& chunk) {
    for (const TimedPose& p : chunk.poses()) {
        if (!trajectory_.empty() && p.stamp_s <= trajectory_.poses().back().stamp_s) {
            throw std::runtime_error(path_ + ":" + std::to_string(lines_) +
                                     ": timestamp not increasing (near this line)");
        }
        trajectory_.append(p.stamp_s, p.T_world_robot);
        ++poses_read_;
    }
}

// Rebuilds without the poses older than t - keep_s (one before that stays, for interpolation).
// Only when the window has doubled, so the cost is amortised O(1) per pose.
void GrowingTrajectory::forgetBefore(double t) {
    const auto& poses = trajectory_.poses();
    const double cut = t - params_.keep_s;
    auto first = std::lower_bound(poses.begin(), poses.end(), cut,
                                  [](const TimedPose& p, double s) { return p.stamp_s < s; });
    if (first != poses.begin()) --first;
    const auto dropped = static_cast<std::size_t>(first - poses.begin());
    if (dropped < 1024 || dropped < poses.size() - dropped) return;
    TumTrajectory kept;
    for (auto it = first; it != poses.end(); ++it) kept.append(it->stamp_s, it->T_world_robot);
    trajectory_ = std::move(kept);
}

std::optional<Eigen::Isometry3d> GrowingTrajectory::poseAt(double t) {
    bool waited = false;
    for (;;) {
        const bool covered = !trajectory_.empty() && trajectory_.poses().back().stamp_s >= t;
        if (covered || stop_.load()) break;
        if (refresh()) continue;
        const auto idle = std::chrono::steady_clock::now() - last_growth_;
        if (std::chrono::duration<double>(idle).count() >= params_.wait_s) break;
        waited = true;
        std::this_thread::sleep_for(std::chrono::duration<double>(params_.poll_period_s));
    }
    if (waited) ++waits_;
    forgetBefore(t);
    return trajectory_.poseAt(t, params_.tolerance_s);
}

}  // namespace stairmap::io
