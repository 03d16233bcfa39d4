// graph.json against docs/graph.schema.json, graph.geojson against the rules of Nav2's GeoJSON
// graph loader, staircases_spot.json against Spot's StaircaseWithLandings field layout.
#include "io/export/GraphJson.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <set>

#include "export/SyntheticLandmarks.h"
#include "io/export/SpotJson.h"
#include "io/json/MiniSchemaValidator.h"

namespace stairmap::io {
namespace {

using nlohmann::json;

exporting::FloorGraph testGraph(std::vector<exporting::RobotProfile>& profiles) {
    test::FlightSpec a, b;
    a.foot = {2.0, 1.0, 0.0};
    a.rise = 0.1875;
    a.risers = 16;
    b.foot = {10.0, 5.0, 0.0};
    b.heading_rad = M_PI / 2;
    b.landing_after = 5;
    const std::vector<StaircaseLandmark> stairs = {test::makeLandmark(3, a, 0, 1),
                                                   test::makeLandmark(7, b, 0, -1)};
    const std::vector<Floor> floors = {test::makeFloor(0, 0.0), test::makeFloor(1, 3.0)};
    profiles.resize(2);
    profiles[0].name = "big";
    profiles[1].name = "small";
    profiles[1].can_ascend = profiles[1].can_descend = false;
    return exporting::buildFloorGraph(stairs, floors, {}, profiles);
}

test::MiniSchemaValidator schema() {
    std::ifstream in(std::string(STAIRMAP_SOURCE_DIR) + "/docs/graph.schema.json");
    EXPECT_TRUE(in.good()) << "docs/graph.schema.json missing";
    return test::MiniSchemaValidator(json::parse(in));
}

TEST(GraphJson, ConformsToTheSchema) {
    std::vector<exporting::RobotProfile> profiles;
    const json doc = graphToJson(testGraph(profiles), profiles, "maps/run1");
    EXPECT_TRUE(schema().validate(doc).empty()) << ::testing::PrintToString(schema().validate(doc));
    EXPECT_EQ(doc.at("nodes").size(), 3u);
    EXPECT_EQ(doc.at("edges").size(), 4u);
    const json& up = doc.at("edges").at(0);
    EXPECT_EQ(up.at("direction"), "up");
    EXPECT_FALSE(up.at("robots").at("small").at("traversable").get<bool>());
    EXPECT_EQ(up.at("robots").at("small").at("reasons").at(0), "cannot climb stairs up");
    EXPECT_EQ(doc.at("edges").at(2).at("landings").size(), 1u);  // stair 7's mid landing
    EXPECT_EQ(doc.at("nodes").at(2).at("kind"), "unknown");
}

TEST(GraphJson, SchemaRejectsBrokenDocuments) {
    std::vector<exporting::RobotProfile> profiles;
    json doc = graphToJson(testGraph(profiles), profiles, "maps/run1");
    doc["edges"][0].erase("to");
    doc["edges"][1]["direction"] = "sideways";
    doc["edges"][2]["robots"]["big"]["traversable"] = "maybe";
    doc["nodes"][0]["z"] = "ground";
    const auto errors = schema().validate(doc);
    const auto has = [&](const std::string& t) {
        return std::any_of(errors.begin(), errors.end(),
                           [&](const std::string& e) { return e.find(t) != std::string::npos; });
    };
    EXPECT_TRUE(has("$.edges[0].to: missing")) << ::testing::PrintToString(errors);
    EXPECT_TRUE(has("$.edges[1].direction: not in enum"));
    EXPECT_TRUE(has("$.edges[2].robots.big.traversable: expected boolean"));
    EXPECT_TRUE(has("$.nodes[0].z: expected number"));
}

/// Nav2's loader takes numbers, booleans, strings, arrays of those and objects as metadata.
bool nav2Metadata(const json& v) {
    if (v.is_object()) {
        return std::all_of(v.begin(), v.end(), [](const json& x) { return nav2Metadata(x); });
    }
    if (v.is_array()) {
        return std::all_of(v.begin(), v.end(), [](const json& x) {
            return x.is_number() || x.is_boolean() || x.is_string();
        });
    }
    return v.is_number() || v.is_boolean() || v.is_string();
}

TEST(GraphGeoJson, Nav2RouteGraphLayout) {
    std::vector<exporting::RobotProfile> profiles;
    const json g = json::parse(graphToGeoJson(testGraph(profiles)).dump());  // as a loader sees it
    EXPECT_EQ(g.at("type"), "FeatureCollection");
    std::set<unsigned> ids, node_ids;
    int nodes = 0, edges = 0;
    for (const json& f : g.at("features")) {
        const json& p = f.at("properties");
        ASSERT_TRUE(p.at("id").is_number_unsigned()) << p.dump();
        EXPECT_TRUE(ids.insert(p.at("id").get<unsigned>()).second) << "duplicate id " << p.at("id");
        EXPECT_TRUE(nav2Metadata(p.at("metadata"))) << p.at("metadata").dump();
        const std::string type = f.at("geometry").at("type");
        if (type == "Point") {
            ++nodes;
            node_ids.insert(p.at("id").get<unsigned>());
            EXPECT_EQ(p.at("frame"), "map");
            EXPECT_GE(f.at("geometry").at("coordinates").size(), 2u);
        } else {
            ASSERT_EQ(type, "MultiLineString");
            ++edges;
            EXPECT_TRUE(p.at("cost").is_number());
        }
    }
    EXPECT_EQ(nodes, 3);
    EXPECT_EQ(edges, 4);
    for (const json& f : g.at("features")) {
        const json& p = f.at("properties");
        if (!p.contains("startid")) continue;
        EXPECT_TRUE(node_ids.count(p.at("startid").get<unsigned>()));
        EXPECT_TRUE(node_ids.count(p.at("endid").get<unsigned>()));
    }
}

TEST(SpotJson, StaircaseWithLandingsLayout) {
    test::FlightSpec f;
    f.foot = {1.0, 2.0, 0.5};
    f.heading_rad = M_PI / 2;
    const auto spot = exporting::toSpotStaircases(test::makeLandmark(4, f, 0, 1));
    const json doc = spotStaircasesToJson(spot);
    ASSERT_EQ(doc.at("staircases").size(), 1u);
    const json& s = doc.at("staircases").at(0);
    const json& pose = s.at("staircase").at("stair_tform").at("frame_tform_stairs");
    EXPECT_DOUBLE_EQ(pose.at("position").at("x").get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(pose.at("position").at("z").get<double>(), 0.5);
    // A 90 deg yaw about Z: (x, y, z, w) = (0, 0, sin 45, cos 45).
    EXPECT_NEAR(pose.at("rotation").at("z").get<double>(), std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(pose.at("rotation").at("w").get<double>(), std::sqrt(0.5), 1e-12);
    EXPECT_EQ(s.at("staircase").at("steps").size(), 10u);
    EXPECT_NEAR(s.at("staircase").at("steps").at(1).at("point").at("x").get<double>(), 0.28, 1e-9);
    EXPECT_NEAR(s.at("staircase").at("average_width").at("width").get<double>(), 1.0, 1e-9);
    EXPECT_TRUE(s.at("bottom_landing").contains("stairs_tform_landing_center"));
    EXPECT_NEAR(s.at("top_landing").at("landing_extent_y").get<double>(), 0.5, 1e-9);
}

}  // namespace
}  // namespace stairmap::io
