#include "pipeline/Mapper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/ScanSimulator.h"
#include "sim/SensorModel.h"
#include "sim/StairGenerators.h"

namespace stairmap::pipeline {
namespace {

constexpr double kBase = 0.35;  // robot origin above the floor [m]

/// One 8-riser flight (rise 0.17, run 0.28, width 1.2) whose foot is at x = 3, ascending +x,
/// on a 20 x 20 m floor; the robot drives from x = -1 towards it (yawed 0) at 10 Hz.
struct StairScene {
    sim::Scene scene;
    std::vector<Scan> scans;

    explicit StairScene(int num_scans, double step_m = 0.1) {
        sim::addFloor(scene, {-10, -10}, {10, 10}, 0.0);
        sim::StraightStairParams stair;
        stair.origin = Eigen::Vector3d(3, 0, 0);
        sim::addStraightStair(scene, stair);
        sim::SensorParams sensor = sim::vlp16();
        sensor.horizontal_resolution_deg = 0.4;
        std::mt19937 rng(5);
        for (int i = 0; i < num_scans; ++i) {
            Scan scan;
            scan.index = i;
            scan.stamp_s = 100.0 + 0.1 * i;
            scan.sensor_label = "lidar";
            scan.T_world_robot.translation() = Eigen::Vector3d(-1.0 + step_m * i, 0.0, kBase);
            scan.points_robot = sim::simulateScan(scene, scan.T_world_robot, sensor, rng, 0.1 * i);
            scans.push_back(std::move(scan));
        }
    }
};

MapperParams testParams() {
    MapperParams p;
    p.sensor.robot_height_m = kBase;
    p.scheduling.distance_m = 0.5;
    return p;
}

TEST(Mapper, MapsOneStaircaseWithTrueGeometryAndReportsEachDetection) {
    const StairScene world(20);
    const StaircaseTruth& truth = world.scene.truth().staircases.at(0);
    Mapper mapper(testParams());
    std::vector<DetectionRecord> records;
    int changes = 0;
    mapper.setDetectionCallback([&](const DetectionRecord& r) { records.push_back(r); });
    mapper.setLandmarksChangedCallback([&](const LandmarkMap&) { ++changes; });
    for (const Scan& scan : world.scans) mapper.processScan(scan);

    ASSERT_EQ(mapper.landmarks().staircases().size(), 1u);
    const StaircaseLandmark& lm = mapper.landmarks().staircases()[0];
    EXPECT_NEAR(lm.stairs.step_height, truth.rise_m, 0.01);
    EXPECT_NEAR(lm.stairs.step_depth, truth.run_m, 0.015);
    EXPECT_NEAR(lm.stairs.step_width, truth.width_m, 0.10);
    EXPECT_NEAR(std::remainder(lm.stairs.heading_rad, 2 * M_PI), 0.0, 5 * M_PI / 180);  // uphill +x
    EXPECT_NEAR((lm.stairs.location - truth.nosings[0].centre()).norm(), 0.0, 0.10);

    // 1.9 m travelled, a run every 0.5 m: runs at 0, 0.5, 1.0, 1.5 m.
    EXPECT_EQ(mapper.stats().detector_runs, 4u);
    EXPECT_EQ(records.size(), mapper.stats().detections);
    ASSERT_FALSE(records.empty());
    for (const auto& r : records) EXPECT_EQ(r.update.landmark_id, lm.id);
    EXPECT_GE(changes, 1);
    EXPECT_EQ(lm.observations, static_cast<int>(records.size()));
}

TEST(Mapper, VoxelMapAndCountersFollowTheScans) {
    const StairScene world(6);
    MapperParams params = testParams();
    params.map.insert_every_n_scans = 3;
    Mapper mapper(params);
    for (const Scan& scan : world.scans) mapper.processScan(scan);
    EXPECT_EQ(mapper.stats().scans, 6u);
    EXPECT_EQ(mapper.stats().voxel_insertions, 2u);  // scans 0 and 3
    EXPECT_LE(mapper.stats().points_used, mapper.stats().points_in);
    // The floor (z = 0) ahead of the robot: its lowest ring hits it 1.31 m away, at x = 0.31.
    EXPECT_TRUE(mapper.voxelMap().isOccupied({0.31, 0.0, 0.01}) ||
                mapper.voxelMap().isOccupied({0.31, 0.0, -0.01}));
    int floor_voxels = 0;
    for (const auto& c : mapper.voxelMap().occupiedVoxelCentres()) floor_voxels += std::abs(c.z()) < 0.05;
    EXPECT_GT(floor_voxels, 200);
    EXPECT_NEAR(mapper.stats().logDuration(), 0.5, 1e-9);
}

TEST(Mapper, LabelFilterSkipsOtherSensors) {
    const StairScene world(3);
    MapperParams params = testParams();
    params.sensor.label_filter = "front_lidar";
    Mapper mapper(params);
    for (const Scan& scan : world.scans) mapper.processScan(scan);
    EXPECT_EQ(mapper.stats().scans, 0u);
    EXPECT_EQ(mapper.stats().scans_filtered_label, 3u);
    EXPECT_EQ(mapper.voxelMap().numLeaves(), 0u);
}

TEST(Mapper, EmptyAndNonFiniteScansAreNormal) {
    Mapper mapper(testParams());
    Scan empty;
    mapper.processScan(empty);
    Scan bad;
    bad.index = 1;
    bad.stamp_s = 1.0;
    bad.points_robot = {Eigen::Vector3f(NAN, 0, 0), Eigen::Vector3f(INFINITY, 1, 1)};
    mapper.processScan(bad);
    EXPECT_EQ(mapper.stats().points_used, 0u);
    EXPECT_TRUE(mapper.landmarks().staircases().empty());
}

TEST(Mapper, ContinuesAGivenLandmarkMap) {
    const StairScene world(20);
    Mapper first(testParams());
    for (const Scan& scan : world.scans) first.processScan(scan);
    ASSERT_EQ(first.landmarks().staircases().size(), 1u);
    const int id = first.landmarks().staircases()[0].id;
    Mapper second(testParams(), first.landmarks());
    for (const Scan& scan : world.scans) second.processScan(scan);
    ASSERT_EQ(second.landmarks().staircases().size(), 1u);
    EXPECT_EQ(second.landmarks().staircases()[0].id, id);
    EXPECT_GT(second.landmarks().staircases()[0].observations,
              first.landmarks().staircases()[0].observations);
}

}  // namespace
}  // namespace stairmap::pipeline
