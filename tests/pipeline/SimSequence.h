#pragma once
// Test helper: a short simulated drive through the simulator's two-floor building (known truth),
// in memory: scans in the robot frame with their true poses.

#include <random>
#include <vector>

#include "core/Scan.h"
#include "sim/BuildingGenerator.h"
#include "sim/ScanSimulator.h"
#include "sim/SensorModel.h"
#include "sim/Trajectory.h"

namespace stairmap::testing {

struct SimSequence {
    sim::Scene scene;
    std::vector<Scan> scans;
};

/// Robot frame origin 0.35 m above the floor; VLP-16 mounted 0.3 m above the robot origin.
inline constexpr double kBaseHeight = 0.35;

/// Ground waypoints (x, y, floor z) of a drive that climbs stair_a, crosses floor 1 and comes down
/// stair_b, then returns to the west hall (so stair_a is seen again on the revisit).
inline std::vector<Eigen::Vector3d> twoFloorLoop(double h) {
    return {{5.0, 2.5, 0}, {1.2, 0.8, 0},  {2.0, 0.8, 0},  {6.48, 0.8, h}, {7.5, 0.8, h},
            {7.5, 5.0, h}, {17.0, 5.0, h}, {17.0, 9.2, h}, {17.52, 9.2, h}, {22.0, 9.2, 0},
            {23.0, 9.2, 0}, {23.0, 5.0, 0}, {5.0, 5.0, 0}, {3.0, 2.5, 0}};
}

inline SimSequence makeTwoFloorSequence(double scan_rate_hz, const sim::SensorParams& sensor,
                                        unsigned seed = 7) {
    SimSequence seq;
    sim::BuildingParams building;
    sim::addTwoFloorBuilding(seq.scene, building);
    sim::TrajectoryParams tp;
    tp.waypoints = twoFloorLoop(building.floor_height_m);
    tp.scan_rate_hz = scan_rate_hz;
    tp.base_height_m = kBaseHeight;
    tp.start_time_s = 1000.0;
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
    T_robot_sensor.translation().z() = 0.3;
    std::mt19937 rng(seed);
    for (const auto& sample : sim::sampleTrajectory(tp)) {
        Scan scan;
        scan.index = seq.scans.size();
        scan.stamp_s = sample.stamp_s;
        scan.sensor_label = "lidar";
        scan.T_world_robot = sample.T_world_robot_reported;
        const PointCloud points_sensor = sim::simulateScan(
            seq.scene, sample.T_world_robot_true * T_robot_sensor, sensor, rng, 0.37 * scan.index);
        scan.points_robot.reserve(points_sensor.size());
        const Eigen::Isometry3f T = T_robot_sensor.cast<float>();
        for (const auto& p : points_sensor) scan.points_robot.push_back(T * p);
        seq.scans.push_back(std::move(scan));
    }
    return seq;
}

}  // namespace stairmap::testing
