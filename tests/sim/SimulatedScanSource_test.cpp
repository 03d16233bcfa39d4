// The simulator as a ScanSource: one scan per trajectory sample, robot-frame points that land on
// the scene's surfaces when placed with the true pose.

#include <gtest/gtest.h>

#include "sim/SimulatedScanSource.h"
#include "sim/StairGenerators.h"

namespace stairmap::sim {
namespace {

TEST(SimulatedScanSource, ScansFollowTheTrajectoryAndHitTheFloor) {
    Scene scene;
    addFloor(scene, {-60, -60}, {60, 60}, 0.0);  // the -1 deg ring lands 46 m away
    TrajectoryParams t;
    t.waypoints = {{0, 0, 0}, {3, 0, 0}};
    t.speed_mps = 1.0;
    t.scan_rate_hz = 1.0;
    t.base_height_m = 0.5;
    SensorParams sensor = vlp16();
    sensor.horizontal_resolution_deg = 2.0;
    sensor.range_noise_std_m = 0.0;
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
    T_robot_sensor.translation().z() = 0.3;
    SimulatedScanSource source(scene, sensor, T_robot_sensor, sampleTrajectory(t), 5);
    std::size_t count = 0;
    while (auto scan = source.next()) {
        EXPECT_EQ(scan->index, count);
        EXPECT_NEAR(scan->T_world_robot.translation().x(), static_cast<double>(count), 1e-9);
        // Only the 8 downward rings reach the floor: 180 azimuths x 8.
        EXPECT_EQ(scan->points_robot.size(), 180u * 8u);
        for (const auto& p : scan->points_robot) {
            const Eigen::Vector3d world = scan->T_world_robot * p.cast<double>();
            EXPECT_NEAR(world.z(), 0.0, 1e-4);
        }
        ++count;
    }
    EXPECT_EQ(count, 4u);
    EXPECT_FALSE(source.next());
}

}  // namespace
}  // namespace stairmap::sim
