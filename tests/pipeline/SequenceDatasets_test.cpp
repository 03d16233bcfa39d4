// `stairmap map` on the bundled short per-kind sequences (datasets/sequences/<kind>), scored against
// each sequence's own gt.json (the simulator's world-frame truth, independent of the mapper), and
// `stairmap eval` scoring several maps into one table.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <filesystem>
#include <string>

#include "pipeline/CliRunner.h"

namespace stairmap::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kPreset = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

std::string mapArgs(const std::string& kind, const fs::path& out) {
    const std::string dir = datasetPath("sequences/" + kind + "/");
    return "map '" + dir + "seq_" + kind + ".rawlog' --poses '" + dir + "poses.tum' --config '" +
           kPreset + "' --out '" + out.string() + "'";
}

Eigen::Vector3d vec(const json& a) {
    return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()};
}

/// Distance from p to the segment [a, b].
double segmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

std::vector<const json*> confirmed(const json& landmarks) {
    std::vector<const json*> out;
    for (const auto& s : landmarks["staircases"])
        if (s["confirmed"].get<bool>()) out.push_back(&s);
    return out;
}

class SequenceRun : public ::testing::Test {
protected:
    // A failed assertion here would make gtest report every test of the suite as skipped, so
    // the failure is recorded and each test fails on it in SetUp().
    static void SetUpTestSuite() {
        out_ = new fs::path(scratch("sequences"));
        setup_error_ = new std::string;
        for (const char* kind : {"ascending", "descending", "room", "negatives"}) {
            const CliResult r = runStairmap(mapArgs(kind, *out_ / kind), *out_);
            if (r.exit_code != 0) {
                *setup_error_ += std::string(kind) + ": exit " + std::to_string(r.exit_code) + ": " + r.err;
            }
        }
    }
    static void TearDownTestSuite() {
        std::error_code ignored;
        fs::remove_all(*out_, ignored);
        delete out_;
        delete setup_error_;
    }
    void SetUp() override { ASSERT_TRUE(setup_error_->empty()) << *setup_error_; }
    static fs::path* out_;
    static std::string* setup_error_;
};
fs::path* SequenceRun::out_ = nullptr;
std::string* SequenceRun::setup_error_ = nullptr;

/// The map of datasets/sequences/<kind> has exactly one confirmed landmark, and it is the flight of
/// the sequence's gt.json: rise / run / width, steps, and location. A map stores flights in
/// canonical form whichever way the robot saw them (docs/landmarks.md): direction "ascending",
/// location = centre of the lowest nosing.
void expectOneTrueLandmark(const fs::path& out, const std::string& kind) {
    SCOPED_TRACE(kind);
    const json map = readJson(out / kind / "landmarks.json");
    const json gt = readJson(datasetPath("sequences/" + kind + "/gt.json"));
    ASSERT_EQ(gt["staircases"].size(), 1u);
    const json& truth = gt["staircases"][0];
    const auto found = confirmed(map);
    ASSERT_EQ(found.size(), 1u) << map.dump(1);
    const json& lm = *found.front();
    EXPECT_EQ(lm["direction"], "ascending");
    EXPECT_NEAR(lm["step_height"].get<double>(), truth["rise_m"].get<double>(), 0.01);
    EXPECT_NEAR(lm["step_depth"].get<double>(), truth["run_m"].get<double>(), 0.015);
    // Width is the weakest estimate (partly seen end edges; docs/detector.md): 15 cm.
    EXPECT_NEAR(lm["step_width"].get<double>(), truth["width_m"].get<double>(), 0.15);
    EXPECT_GE(lm["num_steps"].get<int>(), 5);
    EXPECT_LE(lm["num_steps"].get<int>(), truth["num_risers"].get<int>());
    const json& lowest = truth["nosings"].front();
    EXPECT_LT(segmentDistance(vec(lm["location"]), vec(lowest["start"]), vec(lowest["end"])), 0.15);
}

TEST_F(SequenceRun, DescendingFlightSeenFromTheTopIsOneTrueLandmark) {
    expectOneTrueLandmark(*out_, "descending");
}

TEST_F(SequenceRun, AscendingFlightIsOneTrueLandmark) { expectOneTrueLandmark(*out_, "ascending"); }

TEST_F(SequenceRun, FurnishedRoomGivesNoConfirmedLandmark) {
    const json map = readJson(*out_ / "room/landmarks.json");
    ASSERT_TRUE(readJson(datasetPath("sequences/room/gt.json"))["staircases"].empty());
    EXPECT_TRUE(confirmed(map).empty()) << map.dump(1);
}

// Ramps of 6 and 14 deg, a 2-step stage, 0.45 m bleachers and a curb: the stage's three nosings are
// a valid partial detection for the preset (min_steps 3), but never a confirmed landmark.
TEST_F(SequenceRun, NegativesGiveNoConfirmedLandmark) {
    const json map = readJson(*out_ / "negatives/landmarks.json");
    ASSERT_TRUE(readJson(datasetPath("sequences/negatives/gt.json"))["staircases"].empty());
    EXPECT_TRUE(confirmed(map).empty()) << map.dump(1);
}

TEST_F(SequenceRun, EvalScoresSeveralMapsIntoOnePerKindTable) {
    const std::string args = "eval --json --confirmed-only '" +
                             (*out_ / "ascending/landmarks.json").string() + "' '" +
                             (*out_ / "room/landmarks.json").string() + "' --gt '" +
                             datasetPath("sequences/ascending/gt.json") + "' --gt '" +
                             datasetPath("sequences/room/gt.json") + "'";
    const CliResult r = runStairmap(args, *out_);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json report = json::parse(r.out);
    ASSERT_EQ(report["samples"].size(), 2u);
    bool saw_ascending = false, saw_negative = false;
    for (const auto& row : report["kinds"]) {
        if (row["kind"] == "ascending") {
            saw_ascending = true;
            EXPECT_EQ(row["samples"], 1);
            EXPECT_EQ(row["detections"], 1);
            EXPECT_EQ(row["false_positives"], 0);
            EXPECT_TRUE(row["mean_time_ms"].is_number()) << "time/det from the map's stats.json";
        } else if (row["kind"] == "negative") {
            saw_negative = true;
            EXPECT_EQ(row["samples"], 0);
            EXPECT_EQ(row["false_positives"], 0);
        }
    }
    EXPECT_TRUE(saw_ascending && saw_negative) << report.dump(1);
}

TEST_F(SequenceRun, EvalRejectsMismatchedTruthCountWithOneLine) {
    const std::string args = "eval '" + (*out_ / "ascending/landmarks.json").string() + "' '" +
                             (*out_ / "room/landmarks.json").string() + "' --gt a.json --gt b.json --gt c.json";
    const CliResult r = runStairmap(args, *out_);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("3 --gt files for 2 inputs"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace stairmap::testing
