// `stairmap eval` inputs: pairing several maps with their own truths, confirmed-only landmarks,
// and a map's detector time from the stats.json beside it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/eval/EvalInputs.h"
#include "io/json/GroundTruthJson.h"
#include "io/json/StaircaseJson.h"

namespace stairmap::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(STAIRMAP_TEST_TMP) / "EvalInputs" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

Staircase threeStepFlight(double x0) {
    Staircase s;
    for (int i = 0; i < 3; ++i) {
        StairEdge e;
        e.start = {x0 + 0.3 * i, -0.5, 0.17 * (i + 1)};
        e.end = {x0 + 0.3 * i, 0.5, 0.17 * (i + 1)};
        s.steps.push_back(e);
    }
    s.step_height = 0.17;
    s.step_depth = 0.3;
    s.step_width = 1.0;
    s.location = {x0, 0, 0.17};
    return s;
}

/// A landmarks.json like `stairmap map` writes: two landmarks, the second not confirmed.
void writeMap(const fs::path& dir, bool with_stats) {
    json a = toJson(threeStepFlight(0.0));
    a["confirmed"] = true;
    json b = toJson(threeStepFlight(5.0));
    b["confirmed"] = false;
    std::ofstream(dir / "landmarks.json") << json{{"generator", "test"}, {"staircases", {a, b}}}.dump();
    if (with_stats) std::ofstream(dir / "stats.json") << R"({"stage_mean_ms": {"detect_per_run": 1.25}})";
}

TEST(EvalInputs, ConfirmedOnlyDropsTentativeLandmarksAndStatsGiveTheTime) {
    const fs::path dir = freshDir("confirmed");
    writeMap(dir, true);
    writeGroundTruthFile((dir / "gt.json").string(), SceneTruth{}, {{"kind", "negative"}});
    const std::string map = (dir / "landmarks.json").string();
    const auto all = loadDetectionSample(map, (dir / "gt.json").string());
    EXPECT_EQ(all.detections.size(), 2u);
    EXPECT_EQ(all.name, map);  // maps keep their path: they are all called landmarks.json
    EXPECT_EQ(all.kind, "negative");
    ASSERT_TRUE(all.time_ms.has_value());
    EXPECT_DOUBLE_EQ(*all.time_ms, 1.25);
    DetectionLoadOptions options;
    options.confirmed_only = true;
    const auto confirmed = loadDetectionSample(map, (dir / "gt.json").string(), options);
    ASSERT_EQ(confirmed.detections.size(), 1u);
    EXPECT_DOUBLE_EQ(confirmed.detections[0].location.x(), 0.0);
}

TEST(EvalInputs, MapWithoutStatsHasNoTime) {
    const fs::path dir = freshDir("nostats");
    writeMap(dir, false);
    writeGroundTruthFile((dir / "gt.json").string(), SceneTruth{});
    const auto sample = loadDetectionSample((dir / "landmarks.json").string(), (dir / "gt.json").string());
    EXPECT_FALSE(sample.time_ms.has_value());
}

TEST(EvalInputs, PairsOneTruthPerInputInOrder) {
    const fs::path dir = freshDir("pairs");
    for (const char* sub : {"a", "b"}) {
        fs::create_directories(dir / sub);
        writeMap(dir / sub, false);
    }
    const std::string a = (dir / "a/landmarks.json").string(), b = (dir / "b/landmarks.json").string();
    const auto pairs = pairDetectionFilesWithTruth({b, a}, {"gb.json", "ga.json"});
    ASSERT_EQ(pairs.size(), 2u);
    EXPECT_EQ(pairs[0].first, b);
    EXPECT_EQ(pairs[0].second, "gb.json");
    EXPECT_EQ(pairs[1].first, a);
    EXPECT_EQ(pairs[1].second, "ga.json");
    // One truth for all, or none (each file's own <stem>.gt.json).
    const auto shared = pairDetectionFilesWithTruth({a, b}, {"g.json"});
    ASSERT_EQ(shared.size(), 2u);
    EXPECT_EQ(shared[1].second, "g.json");
    EXPECT_FALSE(pairDetectionFilesWithTruth({a}, {})[0].second.has_value());
}

TEST(EvalInputs, PairingRejectsWrongCountsAndDirectories) {
    const fs::path dir = freshDir("pair_errors");
    fs::create_directories(dir / "a");
    writeMap(dir / "a", false);
    const std::string a = (dir / "a/landmarks.json").string();
    try {
        pairDetectionFilesWithTruth({a}, {"x.json", "y.json", "z.json"});
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("3 --gt files for 1 inputs"), std::string::npos) << e.what();
    }
    try {
        pairDetectionFilesWithTruth({(dir / "a").string(), a}, {"x.json", "y.json"});
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("a directory cannot be paired"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace stairmap::io
