// gt.json round trip and malformed documents.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/json/GroundTruthJson.h"

namespace stairmap::io {
namespace {

SceneTruth sampleTruth() {
    SceneTruth t;
    t.frame = "robot";
    t.floor_heights = {-0.35, 2.65};
    t.observer_floor_z = -0.35;
    StaircaseTruth s;
    s.name = "stair_a";
    s.kind = StairKind::Spiral;
    s.rise_m = 0.1875;
    s.run_m = 0.28;
    s.width_m = 1.2;
    s.num_risers = 2;
    s.bottom_z = -0.35;
    s.top_z = 0.025;
    s.seen_as = StairDirection::Descending;
    s.nosings = {{{1.0 / 3.0, -0.6, -0.1625}, {1.0 / 3.0, 0.6, -0.1625}},
                 {{0.6133, -0.6, 0.025}, {0.6133, 0.6, 0.025}}};
    StaircaseTruth u = s;
    u.name = "stair_b";
    u.kind = StairKind::Hollow;
    u.seen_as.reset();
    t.staircases = {s, u};
    return t;
}

std::string tempFile(const std::string& name, const std::string& content = "") {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "sim_gt";
    std::filesystem::create_directories(dir);
    const auto path = (dir / name).string();
    if (!content.empty()) std::ofstream(path) << content;
    return path;
}

TEST(SimGroundTruthJson, FileRoundTripKeepsEveryField) {
    const SceneTruth truth = sampleTruth();
    const std::string path = tempFile("round_trip.gt.json");
    writeGroundTruthFile(path, truth, {{"scene", "x"}, {"kind", "spiral"}});
    const SceneTruth back = readGroundTruthFile(path);
    EXPECT_EQ(back.frame, "robot");
    EXPECT_EQ(back.floor_heights, truth.floor_heights);
    ASSERT_TRUE(back.observer_floor_z);
    EXPECT_DOUBLE_EQ(*back.observer_floor_z, -0.35);
    ASSERT_EQ(back.staircases.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        const auto& a = truth.staircases[i];
        const auto& b = back.staircases[i];
        EXPECT_EQ(a.name, b.name);
        EXPECT_EQ(a.kind, b.kind);
        EXPECT_EQ(a.seen_as, b.seen_as);
        EXPECT_DOUBLE_EQ(a.rise_m, b.rise_m);
        EXPECT_DOUBLE_EQ(a.run_m, b.run_m);
        EXPECT_DOUBLE_EQ(a.width_m, b.width_m);
        EXPECT_EQ(a.num_risers, b.num_risers);
        EXPECT_DOUBLE_EQ(a.top_z, b.top_z);
        ASSERT_EQ(a.nosings.size(), b.nosings.size());
        for (std::size_t k = 0; k < a.nosings.size(); ++k) {
            EXPECT_EQ(a.nosings[k].start, b.nosings[k].start);  // exact: JSON keeps doubles
            EXPECT_EQ(a.nosings[k].end, b.nosings[k].end);
        }
    }
}

TEST(SimGroundTruthJson, MalformedDocumentsNameFileAndKey) {
    auto j = groundTruthToJson(sampleTruth());
    j["staircases"][1]["nosings"][0]["end"] = {1.0, "a", 2.0};
    try {
        groundTruthFromJson(j, "bad.gt.json");
        FAIL();
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("bad.gt.json"), std::string::npos) << what;
        EXPECT_NE(what.find("staircases[1].nosings[0].end"), std::string::npos) << what;
    }
    auto k = groundTruthToJson(sampleTruth());
    k["staircases"][0].erase("rise_m");
    EXPECT_THROW(groundTruthFromJson(k, "x"), std::runtime_error);
    EXPECT_THROW(groundTruthFromJson(nlohmann::json::object(), "x"), std::runtime_error);
    EXPECT_THROW(readGroundTruthFile(tempFile("truncated.gt.json", "{\"format\": \"stairmap-gt\", ")),
                 std::runtime_error);
    EXPECT_THROW(readGroundTruthFile(tempFile("missing_file_never_written.gt.json")), std::runtime_error);
}

}  // namespace
}  // namespace stairmap::io
