// `stairmap merge` on the bundled two-robot sequence (datasets/two_robot): each robot's poses are
// moved by known transforms, the moved logs are mapped with `stairmap map`, and merge must
// recover the inverse transforms (5 cm, 1 deg), fuse one landmark per staircase with provenance
// from both maps, refuse the robots' own pair (they saw stair_a from opposite ends, so its along-
// flight offset is ambiguous), merge it once the transform is given, and refuse a different flight.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "CliRunner.h"
#include "fleet/Transform4.h"
#include "io/rawlog/TumTrajectory.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using fleet::Transform4;

struct MovedLog {
    std::string robot;  ///< "a" or "b"
    Transform4 T;       ///< poses moved by T: p_moved = T * p_world
};

/// Transforms tried (x, y, z [m], yaw [rad]); yaw near +-180 deg included.
const std::vector<MovedLog>& movedLogs() {
    static const std::vector<MovedLog> logs = {
        {"b", {3.0, -2.0, 0.5, 170.0 * M_PI / 180}},  {"b", {-6.0, 4.0, -1.2, -M_PI / 2}},
        {"b", {0.5, 0.3, 2.0, M_PI / 4}},             {"b", {10.0, -10.0, 0.0, 179.5 * M_PI / 180}},
        {"a", {-4.0, 1.0, -1.0, -100 * M_PI / 180}},  {"a", {2.0, 2.0, 3.0, -179.6 * M_PI / 180}}};
    return logs;
}

std::string dataset(const std::string& file) {
    return std::string(STAIRMAP_SOURCE_DIR) + "/datasets/" + file;
}

std::string mapArgs(const std::string& rawlog, const std::string& poses, const fs::path& out) {
    return "map '" + rawlog + "' --poses '" + poses + "' --config '" + STAIRMAP_SOURCE_DIR +
           "/config/sim_legged_vlp16.ini' --quiet --out '" + out.string() + "'";
}

void movePoses(const std::string& in, const std::string& out, const Transform4& T) {
    const io::TumTrajectory source = io::TumTrajectory::load(in);
    io::TumTrajectory moved;
    for (const auto& p : source.poses()) moved.append(p.stamp_s, T.isometry() * p.T_world_robot);
    moved.save(out);
}

class MergeTwoRobots : public ::testing::Test {
protected:
    /// Maps robot_a, robot_b and every moved log once per process (ctest runs each test in its
    /// own process). Any failure fails every test of the suite (checked in SetUp).
    static void SetUpTestSuite() {
        dir_ = fs::path(STAIRMAP_TEST_TMP) / "merge" / std::to_string(::getpid());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        error_.clear();
        auto map = [](const std::string& robot, const std::string& poses, const std::string& name) {
            const auto r = runStairmap(mapArgs(dataset("two_robot/robot_" + robot + ".rawlog"),
                                               poses, dir_ / name), dir_.string());
            if (r.exit_code != 0) error_ += "map " + name + " failed: " + r.err + "\n";
        };
        map("a", dataset("two_robot/robot_a_poses.tum"), "a");
        map("b", dataset("two_robot/robot_b_poses.tum"), "b");
        for (std::size_t i = 0; i < movedLogs().size(); ++i) {
            const MovedLog& m = movedLogs()[i];
            const std::string poses = (dir_ / ("moved" + std::to_string(i) + ".tum")).string();
            movePoses(dataset("two_robot/robot_" + m.robot + "_poses.tum"), poses, m.T);
            map(m.robot, poses, "moved" + std::to_string(i));
        }
        if (!error_.empty()) ADD_FAILURE() << error_;
    }
    static void TearDownTestSuite() {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    void SetUp() override { ASSERT_TRUE(error_.empty()) << "suite set-up failed: " << error_; }

    static std::string landmarks(const std::string& name) {
        return (dir_ / name / "landmarks.json").string();
    }
    static json readJson(const fs::path& p) { return json::parse(readText(p.string())); }

    static fs::path dir_;
    static std::string error_;
};
fs::path MergeTwoRobots::dir_;
std::string MergeTwoRobots::error_;

/// The merged map has exactly one staircase, fed by both input maps.
void expectOneLandmarkFromBoth(const fs::path& out) {
    const json lm = json::parse(readText((out / "landmarks.json").string()));
    ASSERT_EQ(lm["staircases"].size(), 1u);
    const json prov = json::parse(readText((out / "provenance.json").string()));
    ASSERT_EQ(prov["staircases"].size(), 1u);
    std::set<int> maps;
    for (const auto& s : prov["staircases"][0]["sources"]) maps.insert(s["map"].get<int>());
    EXPECT_TRUE(maps.count(0) && maps.count(1)) << prov.dump();
    for (const char* f : {"scene.3Dscene", "overview.png", "alignment.json"})
        EXPECT_GT(fs::file_size(out / f), 0u) << f;
}

TEST_F(MergeTwoRobots, RecoversEveryMovedLogsTransform) {
    for (std::size_t i = 0; i < movedLogs().size(); ++i) {
        const MovedLog& m = movedLogs()[i];
        SCOPED_TRACE("robot " + m.robot + ", case " + std::to_string(i));
        const fs::path out = dir_ / ("merged" + std::to_string(i));
        const auto r = runStairmap("merge '" + landmarks(m.robot) + "' '" +
                                       landmarks("moved" + std::to_string(i)) + "' --quiet --out '" +
                                       out.string() + "'", dir_.string());
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const json a = readJson(out / "alignment.json");
        ASSERT_EQ(a["maps"].size(), 2u);
        EXPECT_EQ(a["maps"][0]["T_first_this"]["x"], 0.0);
        // Truth: the moved log's frame is T * world, the first map's frame is world.
        const Eigen::Isometry3d truth = m.T.isometry().inverse();
        const json& T = a["maps"][1]["T_first_this"];
        const double dx = T["x"].get<double>() - truth.translation().x();
        const double dy = T["y"].get<double>() - truth.translation().y();
        const double dz = T["z"].get<double>() - truth.translation().z();
        const double yaw_true = std::atan2(truth.linear()(1, 0), truth.linear()(0, 0));
        const double dyaw = fleet::wrapAngle(T["yaw_deg"].get<double>() * M_PI / 180 - yaw_true) *
                            180 / M_PI;
        std::printf("[ merge    ] robot %s moved by (%.1f, %.1f, %.1f m, %.1f deg): error xy %.1f cm,"
                    " z %.1f cm, yaw %.2f deg\n", m.robot.c_str(), m.T.x, m.T.y, m.T.z,
                    m.T.yaw_rad * 180 / M_PI, 100 * std::hypot(dx, dy), 100 * std::abs(dz), dyaw);
        EXPECT_LT(std::hypot(dx, dy), 0.05);
        EXPECT_LT(std::abs(dz), 0.05);
        EXPECT_LT(std::abs(dyaw), 1.0);
        EXPECT_EQ(a["maps"][1]["pairs"].size(), 1u);
        expectOneLandmarkFromBoth(out);
    }
}

TEST_F(MergeTwoRobots, OppositeEndsOfOneFlightAreRefusedUntilTheTransformIsGiven) {
    const fs::path out = dir_ / "ab";
    const auto refused = runStairmap("merge '" + landmarks("a") + "' '" + landmarks("moved0") +
                                         "' --out '" + out.string() + "'", dir_.string());
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.err.find("cannot align"), std::string::npos) << refused.err;
    EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
    EXPECT_FALSE(fs::exists(out / "landmarks.json"));

    // Given robot b's transform, the two robots' views fuse into one stair_a.
    const Eigen::Isometry3d T = movedLogs()[0].T.isometry().inverse();
    char align[160];
    std::snprintf(align, sizeof(align), "moved0=%.6f,%.6f,%.6f,%.6f", T.translation().x(),
                  T.translation().y(), T.translation().z(),
                  std::atan2(T.linear()(1, 0), T.linear()(0, 0)) * 180 / M_PI);
    const auto given = runStairmap("merge '" + landmarks("a") + "' '" + landmarks("moved0") +
                                       "' --align " + align + " --quiet --out '" + out.string() + "'",
                                   dir_.string());
    ASSERT_EQ(given.exit_code, 0) << given.err;
    expectOneLandmarkFromBoth(out);
}

TEST_F(MergeTwoRobots, ThirdMapAlignsToTheFusedPairOfRobots) {
    // a + b (same world frame, given) see stair_a from both ends; robot b's moved log then aligns
    // to that fused flight without help.
    const fs::path out = dir_ / "abm";
    const auto r = runStairmap("merge '" + landmarks("a") + "' '" + landmarks("b") + "' '" +
                                   landmarks("moved1") + "' --align b=0,0,0,0 --quiet --out '" +
                                   out.string() + "'", dir_.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json a = readJson(out / "alignment.json");
    const Eigen::Isometry3d truth = movedLogs()[1].T.isometry().inverse();
    const json& T = a["maps"][2]["T_first_this"];
    EXPECT_NEAR(T["x"].get<double>(), truth.translation().x(), 0.05);
    EXPECT_NEAR(T["y"].get<double>(), truth.translation().y(), 0.05);
    EXPECT_NEAR(T["z"].get<double>(), truth.translation().z(), 0.05);
    const json prov = readJson(out / "provenance.json");
    ASSERT_EQ(prov["staircases"].size(), 1u);
    EXPECT_EQ(prov["staircases"][0]["sources"].size(), 3u);
}

TEST_F(MergeTwoRobots, DifferentFlightIsRefused) {
    // The ascending sequence's flight (rise 0.17 m) is not stair_a (0.1875 m).
    const fs::path seq = dir_ / "ascending";
    const auto mapped = runStairmap(
        mapArgs(dataset("sequences/ascending/seq_ascending.rawlog"),
                dataset("sequences/ascending/poses.tum"), seq), dir_.string());
    ASSERT_EQ(mapped.exit_code, 0) << mapped.err;
    const auto r = runStairmap("merge '" + landmarks("b") + "' '" + (seq / "landmarks.json").string() +
                                   "' --out '" + (dir_ / "none").string() + "'", dir_.string());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no shared staircase"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stairmap::test
