// Scene INI loading: every bundled scene builds; bad values name the file, section and key.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/config/SceneIni.h"

namespace stairmap::io {
namespace {

namespace fs = std::filesystem;

std::string writeIni(const std::string& name, const std::string& content) {
    const auto dir = fs::path(STAIRMAP_TEST_TMP) / "sim_ini";
    fs::create_directories(dir);
    const auto path = (dir / name).string();
    std::ofstream(path) << content;
    return path;
}

TEST(SimSceneIni, EveryBundledSceneLoads) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(STAIRMAP_SOURCE_DIR) / "config/scenes")) {
        if (entry.path().extension() != ".ini") continue;
        SCOPED_TRACE(entry.path().string());
        const auto config = loadSimulationConfig(entry.path().string());
        EXPECT_FALSE(config.scene.primitives().empty());
        EXPECT_TRUE(!config.robots.empty() || !config.cloud_poses.empty());
        ++count;
    }
    EXPECT_GE(count, 13);
}

TEST(SimSceneIni, StraightStairKeysReachTheGenerator) {
    const auto path = writeIni("stair.ini",
                               "[scene]\ntype = hollow\nname = h\n[stair]\nnum_risers = 6\nrise_m = 0.15\n"
                               "run_m = 0.3\nwidth_m = 0.9\n[sensor]\nmodel = os1_64\nmount_pitch_deg = 10\n"
                               "[clouds]\nposes = -2 0 0 0; -3 1 0 45\n");
    const auto config = loadSimulationConfig(path);
    EXPECT_EQ(config.kind, "hollow");
    ASSERT_EQ(config.scene.truth().staircases.size(), 1u);
    const auto& s = config.scene.truth().staircases[0];
    EXPECT_EQ(s.num_risers, 6);
    EXPECT_DOUBLE_EQ(s.rise_m, 0.15);
    EXPECT_DOUBLE_EQ(s.width_m, 0.9);
    EXPECT_EQ(config.sensor.elevations_deg.size(), 64u);
    ASSERT_EQ(config.cloud_poses.size(), 2u);
    EXPECT_DOUBLE_EQ(config.cloud_poses[1].yaw_deg, 45.0);
    // Positive pitch tilts the sensor's x axis down.
    EXPECT_LT((config.T_robot_sensor.linear() * Eigen::Vector3d::UnitX()).z(), -0.1);
}

TEST(SimSceneIni, RobotsCanCarryTheirOwnSensor) {
    const auto path = writeIni("robots.ini",
                               "[scene]\ntype = ascending\n[robot]\nbase_height_m = 0.3\n"
                               "[sensor]\nmodel = vlp16\nlabel = level\n"
                               "[pitched]\nmodel = hdl32\nmount_z_m = 0.4\nmount_pitch_deg = 25\n"
                               "[trajectory]\nrobots = a b\n"
                               "[a]\nsensor = pitched\nbase_height_m = 0.45\nwaypoints = 0 0 0; 1 0 0\n"
                               "[b]\nwaypoints = 0 0 0; 1 0 0\n");
    const auto config = loadSimulationConfig(path);
    ASSERT_EQ(config.robots.size(), 2u);
    const auto& a = config.robots[0];
    const auto& b = config.robots[1];
    EXPECT_EQ(a.mounted.sensor.elevations_deg.size(), 32u);
    EXPECT_EQ(a.mounted.label, "lidar");
    EXPECT_DOUBLE_EQ(a.mounted.T_robot_sensor.translation().z(), 0.4);
    // 25 deg down: the sensor's x axis has z = -sin(25 deg).
    EXPECT_NEAR((a.mounted.T_robot_sensor.linear() * Eigen::Vector3d::UnitX()).z(), -0.4226, 1e-3);
    EXPECT_DOUBLE_EQ(a.trajectory.base_height_m, 0.45);
    EXPECT_EQ(b.mounted.sensor.elevations_deg.size(), 16u);
    EXPECT_EQ(b.mounted.label, "level");
    EXPECT_DOUBLE_EQ((b.mounted.T_robot_sensor.linear() * Eigen::Vector3d::UnitX()).z(), 0.0);
    EXPECT_DOUBLE_EQ(b.trajectory.base_height_m, 0.3);
}

TEST(SimSceneIni, RobotsCanReportPosesInTheirOwnFrame) {
    const auto path = writeIni("odom.ini",
                               "[scene]\ntype = two_floor_building\n[building]\nstair_b_run_m = 0.34\n"
                               "[trajectory]\nrobots = a b\n[a]\nwaypoints = 5 5 0; 6 5 0\n"
                               "[b]\nwaypoints = 5 5 0; 6 5 0\nodom_frame = 3 -2 0.5 90\n");
    const auto config = loadSimulationConfig(path);
    ASSERT_EQ(config.robots.size(), 2u);
    EXPECT_TRUE(config.robots[0].T_world_odom.isApprox(Eigen::Isometry3d::Identity()));
    const Eigen::Isometry3d& T = config.robots[1].T_world_odom;
    EXPECT_TRUE(T.translation().isApprox(Eigen::Vector3d(3, -2, 0.5)));
    // 90 deg about +z: the odom frame's x axis is the world's y axis
    EXPECT_TRUE((T.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
    ASSERT_EQ(config.scene.truth().staircases.size(), 2u);
    EXPECT_DOUBLE_EQ(config.scene.truth().staircases[0].run_m, 0.28);
    EXPECT_DOUBLE_EQ(config.scene.truth().staircases[1].run_m, 0.34);
}

TEST(SimSceneIni, NegativesSceneHoldsEveryPartAndNoStaircase) {
    const auto path = writeIni("park.ini",
                               "[scene]\ntype = negatives\n[negatives]\nparts = r c\n"
                               "[r]\ntype = ramp\nramp_slope_deg = 8\n"
                               "[c]\ntype = curb\norigin_x_m = 10\n"
                               "[trajectory]\nwaypoints = -2 0 0; 12 0 0\nquantum_m = 0.0078125\n"
                               "sort_points = true\nsway_tilt_deg = 1.5\nsway_seed = 9\n");
    const auto config = loadSimulationConfig(path);
    EXPECT_EQ(config.kind, "negative");
    ASSERT_EQ(config.robots.size(), 1u);
    EXPECT_DOUBLE_EQ(config.robots[0].sway.tilt_std_deg, 1.5);
    EXPECT_EQ(config.robots[0].sway.seed, 9u);
    EXPECT_TRUE(config.scene.truth().staircases.empty());
    // The ramp adds its slab, top platform and floor; the curb its box and floor: 5 solids.
    EXPECT_EQ(config.scene.primitives().size(), 5u);
    EXPECT_DOUBLE_EQ(config.rawlog_quantum_m, 0.0078125);
    EXPECT_TRUE(config.rawlog_sort_points);
}

TEST(SimSceneIni, CloudCompressionKeys) {
    const auto path = writeIni("gz.ini",
                               "[scene]\ntype = ascending\n[clouds]\nposes = -2 0 0 0\n"
                               "format = pcd.gz\nquantum_m = 0.0078125\nsort_points = true\n");
    const auto config = loadSimulationConfig(path);
    EXPECT_EQ(config.cloud_extension, "pcd.gz");
    EXPECT_DOUBLE_EQ(config.cloud_params.quantum_m, 0.0078125);
    EXPECT_TRUE(config.cloud_params.sort_points);
    EXPECT_DOUBLE_EQ(config.rawlog_quantum_m, 1.0 / 512.0);  // default: the old 2^-9 m
}

void expectError(const std::string& content, const std::string& needle) {
    // One file per test: ctest runs the tests of this file in parallel processes.
    const auto path = writeIni(
        std::string("bad_") + ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".ini",
        content);
    try {
        loadSimulationConfig(path);
        FAIL() << "expected an error containing " << needle;
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_NE(what.find(needle), std::string::npos) << what;
    }
}

TEST(SimSceneIni, BadValuesNameFileSectionAndKey) {
    const std::string clouds = "[clouds]\nposes = 0 0 0 0\n";
    expectError("[scene]\ntype = ascending\n[stair]\nrise_m = abc\n" + clouds, "[stair] rise_m");
    expectError("[scene]\ntype = ascending\n[stair]\nrise_m = 3\n" + clouds, "rise_m");
    expectError("[scene]\ntype = pyramid\n" + clouds, "[scene] type");
    expectError("[scene]\ntype = ascending\n[sensor]\nmodel = vlp99\n" + clouds, "[sensor]");
    expectError("[scene]\ntype = ascending\n[clouds]\nposes = 0 0 0\n", "[clouds] poses");
    expectError("[scene]\ntype = ascending\n[trajectory]\nwaypoints = 0 0 0\n", "[trajectory] waypoints");
    expectError("[scene]\ntype = ascending\n", "neither a trajectory");
    expectError("[scene]\ntype = ascending\n[trajectory]\nrobots = a\n[a]\nsensor = s\n"
                "waypoints = 0 0 0; 1 0 0\n[s]\nmodel = vlp99\n",
                "[s]");
    expectError("[scene]\ntype = ascending\n" + clouds + "format = las.gz\n", "[clouds] format");
    expectError("[scene]\ntype = ascending\n" + clouds + "quantum_m = 0.5\n", "quantum_m");
    expectError("[scene]\ntype = ascending\n[trajectory]\nwaypoints = 0 0 0; 1 0 0\nquantum_m = 0\n",
                "[trajectory] quantum_m");
    expectError("[scene]\ntype = ascending\n[trajectory]\nwaypoints = 0 0 0; 1 0 0\nsway_tilt_deg = 20\n",
                "[trajectory] sway_tilt_deg");
    expectError("[scene]\ntype = ascending\n[trajectory]\nwaypoints = 0 0 0; 1 0 0\nodom_frame = 1 2 3\n",
                "[trajectory] odom_frame");
    expectError("[scene]\ntype = two_floor_building\n[building]\nstair_b_run_m = 0.9\n" + clouds,
                "stair_b_run_m");
    expectError("[scene]\ntype = negatives\n" + clouds, "[negatives] parts");
    expectError("[scene]\ntype = negatives\n[negatives]\nparts = p\n[p]\ntype = stairs\n" + clouds,
                "[p] type");
    expectError("[scene]\ntype = negatives\n[negatives]\nparts = p\n[p]\ntype = curb\n"
                "curb_height_m = -1\n" + clouds,
                "[p] curb_height_m");
    EXPECT_THROW(loadSimulationConfig("/nonexistent/scene.ini"), std::runtime_error);
}

// Found by fuzz_ini: a bad mount_y_m / mount_z_m threw inside Eigen's comma initializer, whose
// destructor then asserted (abort in debug and sanitizer builds) instead of reporting the key.
TEST(SimSceneIni, BadSensorMountNamesTheKey) {
    const std::string clouds = "[clouds]\nposes = 0 0 0 0\n";
    expectError("[scene]\ntype = ascending\n[sensor]\nmount_y_m = abc\n" + clouds, "[sensor] mount_y_m");
    expectError("[scene]\ntype = ascending\n[sensor]\nmount_z_m = 1e\n" + clouds, "[sensor] mount_z_m");
}

}  // namespace
}  // namespace stairmap::io
