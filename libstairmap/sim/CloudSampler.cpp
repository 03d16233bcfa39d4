#include "sim/CloudSampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tuple>

#include "sim/ScanSimulator.h"

namespace stairmap::sim {

void validate(const CloudSampleParams& p) {
    if (p.scans_per_cloud < 1 || p.scans_per_cloud > 100)
        throw std::invalid_argument("scans_per_cloud: must be 1..100");
    if (p.jitter_xy_m < 0 || p.jitter_xy_m > 0.5)
        throw std::invalid_argument("jitter_xy_m: must be in [0, 0.5] m");
    if (p.jitter_yaw_deg < 0 || p.jitter_yaw_deg > 10)
        throw std::invalid_argument("jitter_yaw_deg: must be in [0, 10] deg");
    if (p.jitter_tilt_deg < 0 || p.jitter_tilt_deg > 10)
        throw std::invalid_argument("jitter_tilt_deg: must be in [0, 10] deg");
    if (!(p.quantum_m >= 0 && p.quantum_m <= 0.05))
        throw std::invalid_argument("quantum_m: must be in [0, 0.05] m");
}

void quantizeAndSort(PointCloud& cloud, double quantum_m, bool sort) {
    if (quantum_m > 0) {
        const float step = static_cast<float>(quantum_m);
        for (auto& p : cloud) {
            for (int i = 0; i < 3; ++i) p[i] = std::round(p[i] / step) * step;
        }
    }
    if (sort) {
        std::sort(cloud.begin(), cloud.end(), [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
            return std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z());
        });
    }
}

PointCloud simulateRobotCloud(const Scene& scene, const Eigen::Isometry3d& T_world_robot,
                              const Eigen::Isometry3d& T_robot_sensor, const SensorParams& sensor,
                              const CloudSampleParams& params, std::mt19937& rng) {
    validate(params);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::uniform_real_distribution<double> azimuth(0.0, sensor.horizontal_resolution_deg);
    PointCloud cloud;
    for (int k = 0; k < params.scans_per_cloud; ++k) {
        Eigen::Isometry3d T_robot_robotk = Eigen::Isometry3d::Identity();
        if (k > 0) {  // the first scan is taken exactly at the sample pose
            T_robot_robotk.translation() << params.jitter_xy_m * gauss(rng),
                params.jitter_xy_m * gauss(rng), 0.0;
            constexpr double kDeg = M_PI / 180.0;
            const double yaw = params.jitter_yaw_deg * kDeg * gauss(rng);
            const double pitch = params.jitter_tilt_deg * kDeg * gauss(rng);
            const double roll = params.jitter_tilt_deg * kDeg * gauss(rng);
            T_robot_robotk.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                       Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                                       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                                          .toRotationMatrix();
        }
        const Eigen::Isometry3d T_robot_sensork = T_robot_robotk * T_robot_sensor;
        const auto scan = simulateScan(scene, T_world_robot * T_robot_sensork, sensor, rng,
                                       k == 0 ? 0.0 : azimuth(rng));
        const Eigen::Isometry3f T = T_robot_sensork.cast<float>();
        for (const auto& p : scan) cloud.push_back(T * p);
    }
    quantizeAndSort(cloud, params.quantum_m, params.sort_points);
    return cloud;
}

SceneTruth truthInRobotFrame(const SceneTruth& world_truth, const Eigen::Isometry3d& T_world_robot,
                             double floor_z_world, double floor_tolerance_m) {
    SceneTruth world = world_truth;
    world.observer_floor_z = floor_z_world;
    for (auto& stair : world.staircases) {
        stair.seen_as.reset();
        if (std::abs(floor_z_world - stair.bottom_z) < floor_tolerance_m) {
            stair.seen_as = StairDirection::Ascending;
        } else if (std::abs(floor_z_world - stair.top_z) < floor_tolerance_m) {
            stair.seen_as = StairDirection::Descending;
        }
    }
    return transformTruth(world, T_world_robot.inverse(), "robot");
}

}  // namespace stairmap::sim
