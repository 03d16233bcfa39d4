#include "pipeline/LevelGuard.h"

#include <cmath>
#include <stdexcept>

namespace stairmap::pipeline {
namespace {

double horizontal(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

constexpr double kMinMotionM = 0.05;  // below this the slope is not measurable (robot still)

}  // namespace

LevelGuard::LevelGuard(double max_slope_deg, double path_window_m)
    : max_slope_tan_(max_slope_deg > 0 ? std::tan(max_slope_deg * M_PI / 180.0) : -1.0),
      path_window_m_(path_window_m) {
    if (!std::isfinite(max_slope_deg) || max_slope_deg >= 90.0) {
        throw std::invalid_argument("SchedulingParams.max_level_slope_deg must be below 90 deg");
    }
    if (!(path_window_m_ > 0)) throw std::invalid_argument("LevelGuard: path window must be > 0");
}

bool LevelGuard::update(const Eigen::Vector3d& position) {
    if (max_slope_tan_ < 0) return true;
    recent_.push_back(position);
    // Keep just enough history to span path_window_m horizontally.
    while (recent_.size() > 2 && horizontal(recent_[1], position) >= path_window_m_) {
        recent_.pop_front();
    }
    const double run = horizontal(recent_.front(), position);
    const double rise = std::abs(position.z() - recent_.front().z());
    if (run >= kMinMotionM || rise >= kMinMotionM) level_ = rise <= max_slope_tan_ * run;
    return level_;
}

}  // namespace stairmap::pipeline
