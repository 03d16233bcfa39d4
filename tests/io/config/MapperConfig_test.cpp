#include "io/config/MapperConfig.h"

#include <gtest/gtest.h>

#include <mrpt/config/CConfigFileMemory.h>

namespace stairmap::io {
namespace {

mrpt::config::CConfigFileMemory ini(const std::string& text) {
    mrpt::config::CConfigFileMemory cfg;
    cfg.setContent(text);
    return cfg;
}

void expectErrorNaming(const std::string& text, const std::string& key) {
    try {
        loadMapperParams(ini(text));
        FAIL() << "no error for: " << text;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
}

TEST(MapperConfig, MissingKeysKeepDefaults) {
    const pipeline::MapperParams p = loadMapperParams(ini(""));
    const pipeline::MapperParams d;
    EXPECT_EQ(p.map.resolution_m, d.map.resolution_m);
    EXPECT_EQ(p.scheduling.window_scans, d.scheduling.window_scans);
    EXPECT_EQ(p.sensor.robot_height_m, d.sensor.robot_height_m);
}

TEST(MapperConfig, ReadsEverySectionOfTheMapper) {
    const pipeline::MapperParams p = loadMapperParams(ini(
        "[sensor]\nrobot_height_m = 0.42\nfloor_from_pose = false\nlabel_filter = velo\n"
        "min_range_m = 0.5\nmax_range_m = 25\n"
        "[map]\nresolution_m = 0.1\ninsertion_mode = raycast\nmax_range_m = 8\n"
        "insert_every_n_scans = 3\n"
        "[scheduling]\ndistance_m = 2\nangle_deg = 45\nperiod_s = 0\nwindow_scans = 7\n"
        "window_s = 1.5\nsubmap_radius_m = 4\nsubmap_leaf_m = 0.03\nmax_level_slope_deg = 12\n"
        "[landmarks]\nconfirm_observations = 5\n"));
    EXPECT_DOUBLE_EQ(p.sensor.robot_height_m, 0.42);
    EXPECT_FALSE(p.sensor.floor_from_pose);
    EXPECT_EQ(p.sensor.label_filter, "velo");
    EXPECT_DOUBLE_EQ(p.sensor.min_range_m, 0.5);
    EXPECT_DOUBLE_EQ(p.sensor.max_range_m, 25);
    EXPECT_DOUBLE_EQ(p.map.resolution_m, 0.1);
    EXPECT_EQ(p.map.insertion_mode, map::VoxelInsertionMode::RayCast);
    EXPECT_DOUBLE_EQ(p.map.max_range_m, 8);
    EXPECT_EQ(p.map.insert_every_n_scans, 3);
    EXPECT_DOUBLE_EQ(p.scheduling.distance_m, 2);
    EXPECT_DOUBLE_EQ(p.scheduling.angle_deg, 45);
    EXPECT_DOUBLE_EQ(p.scheduling.period_s, 0);
    EXPECT_EQ(p.scheduling.window_scans, 7);
    EXPECT_DOUBLE_EQ(p.scheduling.window_s, 1.5);
    EXPECT_DOUBLE_EQ(p.scheduling.submap_radius_m, 4);
    EXPECT_DOUBLE_EQ(p.scheduling.submap_leaf_m, 0.03);
    EXPECT_DOUBLE_EQ(p.scheduling.max_level_slope_deg, 12);
    EXPECT_EQ(p.landmarks.confirm_observations, 5);
}

TEST(MapperConfig, RobotHeightFallsBackToTheDetectorSection) {
    EXPECT_DOUBLE_EQ(loadMapperParams(ini("[detector]\nrobot_height_m = 0.33\n")).sensor.robot_height_m,
                     0.33);
}

TEST(MapperConfig, BadValuesNameSectionAndKey) {
    expectErrorNaming("[map]\nresolution_m = fine\n", "[map] resolution_m");
    expectErrorNaming("[map]\nresolution_m = 0\n", "[map] resolution_m");
    expectErrorNaming("[map]\ninsertion_mode = splat\n", "[map] insertion_mode");
    expectErrorNaming("[map]\ninsert_every_n_scans = 1.5\n", "insert_every_n_scans");
    expectErrorNaming("[scheduling]\nwindow_scans = 0\n", "[scheduling] window_scans");
    expectErrorNaming("[scheduling]\nwindow_s = nan\n", "[scheduling] window_s");
    expectErrorNaming("[sensor]\nfloor_from_pose = maybe\n", "[sensor] floor_from_pose");
    expectErrorNaming("[sensor]\nmin_range_m = 5\nmax_range_m = 2\n", "max_range_m");
    expectErrorNaming("[sensor]\npose_yaw_deg = 720\n", "[sensor] pose_yaw_deg");
    expectErrorNaming("[sensor]\npose_z_m = inf\n", "[sensor] pose_z_m");
}

TEST(MapperConfig, ReadsTheSensorPoseOnTheRobot) {
    const pipeline::SensorParams p = loadMapperParams(ini(
        "[sensor]\npose_x_m = 0.2\npose_y_m = -0.1\npose_z_m = 0.5\n"
        "pose_yaw_deg = 90\npose_pitch_deg = 10\npose_roll_deg = -5\n")).sensor;
    EXPECT_DOUBLE_EQ(p.pose_x_m, 0.2);
    EXPECT_DOUBLE_EQ(p.pose_y_m, -0.1);
    EXPECT_DOUBLE_EQ(p.pose_z_m, 0.5);
    EXPECT_DOUBLE_EQ(p.pose_yaw_deg, 90);
    EXPECT_DOUBLE_EQ(p.pose_pitch_deg, 10);
    EXPECT_DOUBLE_EQ(p.pose_roll_deg, -5);
}

class ShippedConfig : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedConfig, LoadsAndSetsTheRobotHeight) {
    const std::string path = std::string(STAIRMAP_SOURCE_DIR) + "/config/" + GetParam() + ".ini";
    const pipeline::MapperParams p = loadMapperParams(path);
    EXPECT_GE(p.sensor.robot_height_m, 0.0);
    EXPECT_GT(p.map.resolution_m, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Presets, ShippedConfig,
                         ::testing::Values("default", "wheeled_vlp16", "legged_pitched_lidar",
                                           "legged_depth_camera", "sim_legged_vlp16"));

TEST(MapperConfig, MissingFileNamesThePath) {
    try {
        loadMapperParams(std::string("/nonexistent/mapper.ini"));
        FAIL();
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/mapper.ini"), std::string::npos);
    }
}

}  // namespace
}  // namespace stairmap::io
