// alignment.json round trip and field errors; provenance.json layout.
#include <gtest/gtest.h>

#include "io/json/FleetJson.h"

namespace stairmap::io {
namespace {

TEST(FleetJson, AlignmentRoundTrip) {
    std::vector<AlignmentRecord> maps(2);
    maps[0].source = "A/landmarks.json";
    maps[1] = {"B/landmarks.json", {1.5, -2.0, 0.25, M_PI * 0.75}, {0.03, 0.01, 0.4}, {{0, 3}, {2, 1}}};
    const nlohmann::json doc = alignmentToJson(maps);
    EXPECT_DOUBLE_EQ(doc["maps"][1]["T_first_this"]["yaw_deg"].get<double>(), 135.0);
    EXPECT_EQ(doc["maps"][1]["pairs"], nlohmann::json::parse("[[0,3],[2,1]]"));
    const std::vector<AlignmentRecord> back = alignmentFromJson(nlohmann::json::parse(doc.dump()));
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].source, "A/landmarks.json");
    EXPECT_DOUBLE_EQ(back[0].T_first_this.x, 0.0);
    EXPECT_NEAR(back[1].T_first_this.yaw_rad, M_PI * 0.75, 1e-12);
    EXPECT_DOUBLE_EQ(back[1].T_first_this.z, 0.25);
    EXPECT_DOUBLE_EQ(back[1].sigma.yaw_deg, 0.4);
    ASSERT_EQ(back[1].pairs.size(), 2u);
    EXPECT_EQ(back[1].pairs[1].first_id, 2);
    EXPECT_EQ(back[1].pairs[1].other_id, 1);
}

TEST(FleetJson, AlignmentErrorsNameTheField) {
    auto doc = alignmentToJson({AlignmentRecord{"A", {}, {}, {{1, 2}}}});
    doc["maps"][0]["pairs"][0] = {1};
    try {
        alignmentFromJson(doc);
        FAIL() << "accepted a one-element pair";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("maps[0].pairs[0]"), std::string::npos) << e.what();
    }
    doc = alignmentToJson({AlignmentRecord{"A", {}, {}, {}}});
    doc["maps"][0]["T_first_this"].erase("z");
    EXPECT_THROW(alignmentFromJson(doc), std::runtime_error);
    EXPECT_THROW(alignmentFromJson(nlohmann::json::object()), std::runtime_error);
}

TEST(FleetJson, ProvenanceLists) {
    fleet::LandmarkProvenance p;
    p.id = 4;
    p.sources = {{0, 4, 3}, {1, 0, 5}};
    p.steps = {{{1, -1, 2}}, {{0, -1, 1}, {1, -1, 2}}};
    const nlohmann::json doc = provenanceToJson({p}, {"A", "B"});
    EXPECT_EQ(doc["maps"], nlohmann::json::parse(R"(["A","B"])"));
    EXPECT_EQ(doc["staircases"][0]["sources"][1]["observations"], 5);
    EXPECT_EQ(doc["staircases"][0]["steps"][1].size(), 2u);
    EXPECT_EQ(doc["staircases"][0]["steps"][0][0]["map"], 1);
}

}  // namespace
}  // namespace stairmap::io
