#include "pipeline/Submap.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_set>

namespace stairmap::pipeline {

double robotYaw(const Eigen::Isometry3d& T_world_robot) {
    const Eigen::Vector3d x_axis = T_world_robot.linear().col(0);
    return std::atan2(x_axis.y(), x_axis.x());
}

Eigen::Isometry3d gravityAlignedFrame(const Eigen::Isometry3d& T_world_robot) {
    Eigen::Isometry3d T_world_grav = Eigen::Isometry3d::Identity();
    T_world_grav.translation() = T_world_robot.translation();
    T_world_grav.linear() =
        Eigen::AngleAxisd(robotYaw(T_world_robot), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return T_world_grav;
}

ScanWindow::ScanWindow(int max_scans, double max_age_s)
    : max_scans_(max_scans), max_age_s_(max_age_s) {
    if (max_scans_ < 1) throw std::invalid_argument("SchedulingParams.window_scans must be >= 1");
    if (!(max_age_s_ > 0)) throw std::invalid_argument("SchedulingParams.window_s must be > 0");
}

void ScanWindow::push(double stamp_s, PointCloud points_world) {
    scans_.push_back(Entry{stamp_s, std::move(points_world)});
    while (static_cast<int>(scans_.size()) > max_scans_) scans_.pop_front();
    while (!scans_.empty() && stamp_s - scans_.front().stamp_s > max_age_s_) scans_.pop_front();
}

std::size_t ScanWindow::numPoints() const {
    std::size_t n = 0;
    for (const auto& e : scans_) n += e.points_world.size();
    return n;
}

PointCloud ScanWindow::extractSubmap(const Eigen::Isometry3d& T_world_grav, double radius_m,
                                     double leaf_m) const {
    const Eigen::Isometry3f T_grav_world = T_world_grav.inverse().cast<float>();
    const float r2 = static_cast<float>(radius_m * radius_m);
    PointCloud cloud;
    cloud.reserve(numPoints());
    for (const auto& e : scans_) {
        for (const auto& p_world : e.points_world) {
            const Eigen::Vector3f p = T_grav_world * p_world;
            if (p.x() * p.x() + p.y() * p.y() <= r2) cloud.push_back(p);
        }
    }
    return leaf_m > 0 ? voxelDownsample(cloud, leaf_m) : cloud;
}

PointCloud voxelDownsample(const PointCloud& cloud, double leaf_m) {
    // 21 bits per axis: +-1M voxels, i.e. +-20 km at 2 cm; farther points would alias (harmless
    // for a local submap, which is radius-limited).
    auto key = [inv = 1.0 / leaf_m](const Eigen::Vector3f& p) {
        auto cell = [inv](float v) {
            return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v * inv)) &
                                              0x1FFFFF);
        };
        return cell(p.x()) | (cell(p.y()) << 21) | (cell(p.z()) << 42);
    };
    std::unordered_set<std::uint64_t> seen;
    seen.reserve(cloud.size());
    PointCloud out;
    out.reserve(cloud.size() / 2);
    for (const auto& p : cloud) {
        if (!p.allFinite()) continue;
        if (seen.insert(key(p)).second) out.push_back(p);
    }
    return out;
}

}  // namespace stairmap::pipeline
