// End-to-end tests of `stairmap map` on the bundled simulated sequences (ground truth in gt.json)
// and on real Velodyne rawlogs (no staircases in them).
#include <gtest/gtest.h>

#include <octomap/OcTree.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "pipeline/CliRunner.h"

namespace stairmap::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kPreset = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

std::string twoFloorArgs(const fs::path& out, const std::string& config = kPreset) {
    return "map '" + datasetPath("two_floor/two_floor.rawlog") + "' --poses '" +
           datasetPath("two_floor/poses.tum") + "' --config '" + config + "' --out '" +
           out.string() + "'";
}

double floorZ(const json& doc, int id) {
    for (const auto& f : doc["floors"]) {
        if (f["id"].get<int>() == id) return f["z"].get<double>();
    }
    return NAN;
}

/// The landmark whose location (centre of its first edge) lies on the truth's first nosing segment
/// (within 0.2 m; the next nosing is >= 0.33 m away), or nullptr. Along the nosing the centre may
/// sit anywhere: a partly seen first edge shifts it sideways (as `stairmap eval` measures location).
const json* landmarkFor(const json& doc, const json& truth) {
    const auto& n0 = truth["nosings"][0];
    Eigen::Vector3d a, b;
    for (int i = 0; i < 3; ++i) {
        a[i] = n0["start"][i].get<double>();
        b[i] = n0["end"][i].get<double>();
    }
    for (const auto& s : doc["staircases"]) {
        const Eigen::Vector3d loc(s["location"][0].get<double>(), s["location"][1].get<double>(),
                                  s["location"][2].get<double>());
        const double t = std::clamp((loc - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        if ((a + t * (b - a) - loc).norm() < 0.2) return &s;
    }
    return nullptr;
}

/// Every staircase of gt.json is in the map once, with its geometry and floors.
void expectMatchesTruth(const json& doc, const json& gt) {
    ASSERT_EQ(doc["staircases"].size(), gt["staircases"].size()) << doc.dump(1);
    for (const auto& truth : gt["staircases"]) {
        SCOPED_TRACE(truth["name"].get<std::string>());
        const json* lm = landmarkFor(doc, truth);
        ASSERT_NE(lm, nullptr) << "no landmark at the first nosing of this staircase";
        EXPECT_NEAR((*lm)["step_height"].get<double>(), truth["rise_m"].get<double>(), 0.01);
        EXPECT_NEAR((*lm)["step_depth"].get<double>(), truth["run_m"].get<double>(), 0.015);
        EXPECT_NEAR((*lm)["step_width"].get<double>(), truth["width_m"].get<double>(), 0.10);
        EXPECT_NEAR(floorZ(doc, (*lm)["bottom_floor"]), truth["bottom_z"].get<double>(), 0.15);
        EXPECT_NEAR(floorZ(doc, (*lm)["top_floor"]), truth["top_z"].get<double>(), 0.15);
    }
}

std::set<int> landmarkIds(const json& doc) {
    std::set<int> ids;
    for (const auto& s : doc["staircases"]) ids.insert(s["id"].get<int>());
    return ids;
}

class TwoFloorRun : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        out_ = new fs::path(scratch("two_floor"));
        result_ = new CliResult(runStairmap(twoFloorArgs(*out_ / "run1"), *out_));
    }
    static void TearDownTestSuite() {
        std::error_code ignored;
        fs::remove_all(*out_, ignored);  // per-process folder: do not let them pile up
        delete out_;
        delete result_;
    }
    static fs::path* out_;
    static CliResult* result_;
};
fs::path* TwoFloorRun::out_ = nullptr;
CliResult* TwoFloorRun::result_ = nullptr;

TEST_F(TwoFloorRun, FindsExactlyTheBuildingsStaircasesOnTheRightFloors) {
    ASSERT_EQ(result_->exit_code, 0) << result_->err;
    EXPECT_TRUE(result_->err.empty()) << result_->err;  // no progress bar off a TTY, no chatter
    const json doc = readJson(*out_ / "run1/landmarks.json");
    EXPECT_EQ(doc["version"], 1);
    EXPECT_EQ(doc["frame"], "world");
    expectMatchesTruth(doc, readJson(datasetPath("two_floor/gt.json")));
}

TEST_F(TwoFloorRun, WritesEveryOutput) {
    ASSERT_EQ(result_->exit_code, 0) << result_->err;
    const fs::path dir = *out_ / "run1";
    for (const char* name : {"landmarks.json", "map.bt", "detections.jsonl", "scene.3Dscene",
                             "overview.png", "stats.json"}) {
        EXPECT_TRUE(fs::exists(dir / name)) << name;
        EXPECT_GT(fs::file_size(dir / name), 0u) << name;
    }
    octomap::OcTree tree(0.1);
    ASSERT_TRUE(tree.readBinary((dir / "map.bt").string()));
    EXPECT_GT(tree.getNumLeafNodes(), 1000u);
    // The ground floor (slab top at z = 0) and the upper floor (z = 3) are in the map.
    int ground = 0, upper = 0;
    for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
        if (!tree.isNodeOccupied(*it)) continue;
        ground += std::abs(it.getZ()) < 0.05;
        upper += std::abs(it.getZ() - 3.0) < 0.05;
    }
    EXPECT_GT(ground, 1000);
    EXPECT_GT(upper, 100);

    const json stats = readJson(dir / "stats.json");
    // One scan per pose in the dataset's trajectory file (the simulator writes one per scan).
    int num_poses = 0;
    std::ifstream poses(datasetPath("two_floor/poses.tum"));
    for (std::string line; std::getline(poses, line);) num_poses += !line.empty() && line[0] != '#';
    ASSERT_GT(num_poses, 10);
    EXPECT_EQ(stats["scans"].get<int>(), num_poses);
    EXPECT_GT(stats["real_time_factor"].get<double>(), 0.0);
    EXPECT_GT(stats["peak_rss_mb"].get<double>(), 1.0);
    EXPECT_TRUE(stats["stage_total_ms"].contains("detect"));

    // Every raw detection is a line naming the landmark it went to (which may since have been
    // joined into an older one: then the map lists it as absorbed into a landmark it has).
    std::ifstream lines(dir / "detections.jsonl");
    const json final_map = readJson(dir / "landmarks.json");
    std::set<int> ids = landmarkIds(final_map);
    for (const auto& a : final_map["continuation"]["absorbed"]) {
        if (ids.count(a["into"].get<int>()) == 1) ids.insert(a["id"].get<int>());
    }
    int count = 0;
    for (std::string line; std::getline(lines, line); ++count) {
        const json d = json::parse(line);
        EXPECT_TRUE(d.contains("robot_pose") && d.contains("staircase") && d.contains("stamp_s"));
        EXPECT_TRUE(ids.count(d["landmark_id"].get<int>()) == 1 || d["landmark_id"] == -1);
    }
    EXPECT_EQ(count, stats["detections"].get<int>());
}

TEST_F(TwoFloorRun, SecondRunWithMapInKeepsIdsAndAddsNothing) {
    ASSERT_EQ(result_->exit_code, 0) << result_->err;
    const fs::path first = *out_ / "run1/landmarks.json";
    const std::string before = readText(first);
    const CliResult second =
        runStairmap(twoFloorArgs(*out_ / "run2") + " --map-in '" + first.string() + "'", *out_);
    ASSERT_EQ(second.exit_code, 0) << second.err;
    EXPECT_EQ(readText(first), before) << "--map-in file was modified";
    const json a = readJson(first);
    const json b = readJson(*out_ / "run2/landmarks.json");
    EXPECT_EQ(landmarkIds(a), landmarkIds(b));
    expectMatchesTruth(b, readJson(datasetPath("two_floor/gt.json")));
    for (const auto& s : b["staircases"]) EXPECT_TRUE(s["confirmed"].get<bool>());
}

TEST(MapCommand, TruncatedRawlogKeepsTheMapUpToTheDamage) {
    const fs::path dir = scratch("truncated");
    const fs::path cut = dir / "cut.rawlog";
    // Uncompress, then keep 55 % of the bytes: the cut falls in the middle of an object.
    ASSERT_EQ(std::system(("gzip -dc < '" + datasetPath("two_floor/two_floor.rawlog") + "' > '" +
                           (dir / "full.rawlog").string() + "'").c_str()), 0);
    const auto size = fs::file_size(dir / "full.rawlog");
    fs::copy_file(dir / "full.rawlog", cut);
    fs::resize_file(cut, size * 55 / 100);
    const CliResult r = runStairmap(
        "map '" + cut.string() + "' --poses '" + datasetPath("two_floor/poses.tum") +
            "' --config '" + kPreset + "' --out '" + (dir / "out").string() + "'", dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(cut.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("index"), std::string::npos) << r.err;
    const json stats = readJson(dir / "out/stats.json");
    EXPECT_GT(stats["scans"].get<int>(), 20);  // ~ half of the 59 scans were mapped
    EXPECT_LT(stats["scans"].get<int>(), 59);
    EXPECT_NO_THROW(readJson(dir / "out/landmarks.json"));
    EXPECT_TRUE(fs::exists(dir / "out/map.bt"));
    EXPECT_TRUE(fs::exists(dir / "out/overview.png"));
}

TEST(MapCommand, TwoRobotsMergeIntoOneLandmarkPerStaircase) {
    const fs::path dir = scratch("two_robot");
    auto args = [&](const std::string& robot, const std::string& out, const std::string& extra) {
        return "map '" + datasetPath("two_robot/" + robot + ".rawlog") + "' --poses '" +
               datasetPath("two_robot/" + robot + "_poses.tum") + "' --config '" + kPreset +
               "' --out '" + (dir / out).string() + "'" + extra;
    };
    const CliResult a = runStairmap(args("robot_a", "a", ""), dir);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const CliResult b = runStairmap(
        args("robot_b", "ab", " --map-in '" + (dir / "a/landmarks.json").string() + "'"), dir);
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const json doc_a = readJson(dir / "a/landmarks.json");
    const json doc_ab = readJson(dir / "ab/landmarks.json");
    ASSERT_EQ(doc_a["staircases"].size(), 1u) << doc_a.dump(1);  // robot_a sees stair_a only
    ASSERT_EQ(doc_ab["staircases"].size(), 1u) << doc_ab.dump(1);
    EXPECT_EQ(doc_ab["staircases"][0]["id"], doc_a["staircases"][0]["id"]);
    EXPECT_GT(doc_ab["staircases"][0]["observations"].get<int>(),
              doc_a["staircases"][0]["observations"].get<int>());
}

class RealVelodyneLog : public ::testing::TestWithParam<std::string> {};

TEST_P(RealVelodyneLog, ProducesNoStaircase) {
    const fs::path dir = scratch("real_" + GetParam());
    const std::string rawlog = std::string(STAIRMAP_SHARED_DIR) + "/data/real/" + GetParam() + ".rawlog";
    ASSERT_TRUE(fs::exists(rawlog)) << rawlog;
    const CliResult r = runStairmap("map '" + rawlog + "' --static-robot --out '" +
                                    (dir / "out").string() + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json stats = readJson(dir / "out/stats.json");
    EXPECT_GT(stats["scans"].get<int>(), 0);
    EXPECT_GT(stats["detector_runs"].get<int>(), 0);
    EXPECT_EQ(readJson(dir / "out/landmarks.json")["staircases"].size(), 0u);
}

INSTANTIATE_TEST_SUITE_P(SharedData, RealVelodyneLog,
                         ::testing::Values("sample_velodyne_vlp16_gps", "test_velodyne_VLP16",
                                           "sample_velodyne_hdl32"));

TEST(MapCommand, BadInputsExitTwoNamingTheProblem) {
    const fs::path dir = scratch("bad");
    std::ofstream(dir / "bad.ini") << "[scheduling]\nwindow_scans = many\n";
    const CliResult r = runStairmap(twoFloorArgs(dir / "out", (dir / "bad.ini").string()), dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("window_scans"), std::string::npos) << r.err;

    std::ofstream(dir / "broken.json") << "{\"version\": 1, \"staircases\": [";
    const CliResult m = runStairmap(twoFloorArgs(dir / "out2") + " --map-in '" +
                                    (dir / "broken.json").string() + "'", dir);
    EXPECT_EQ(m.exit_code, 2);
    EXPECT_NE(m.err.find("broken.json"), std::string::npos) << m.err;
}

}  // namespace
}  // namespace stairmap::testing
