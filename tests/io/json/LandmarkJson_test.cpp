// Persistence of the landmark map: exact round trip, continuation, error handling.
#include <gtest/gtest.h>

#include <fstream>

#include "io/json/LandmarkJson.h"
#include "map/LandmarkTestMaps.h"

namespace stairmap {
namespace {

void expectSameEdge(const StairEdge& a, const StairEdge& b) {
    EXPECT_EQ(a.start, b.start);
    EXPECT_EQ(a.end, b.end);
    EXPECT_EQ(a.cov_rho_theta, b.cov_rho_theta);
    EXPECT_EQ(a.num_points, b.num_points);
}

void expectSameState(const LandmarkMapState& a, const LandmarkMapState& b) {
    ASSERT_EQ(a.staircases.size(), b.staircases.size());
    for (std::size_t i = 0; i < a.staircases.size(); ++i) {
        const StaircaseLandmark &x = a.staircases[i], &y = b.staircases[i];
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.confirmed, y.confirmed);
        EXPECT_EQ(x.observations, y.observations);
        EXPECT_EQ(x.first_seen_s, y.first_seen_s);
        EXPECT_EQ(x.last_seen_s, y.last_seen_s);
        EXPECT_EQ(x.bottom_observed, y.bottom_observed);
        EXPECT_EQ(x.top_observed, y.top_observed);
        EXPECT_EQ(x.bottom_floor, y.bottom_floor);
        EXPECT_EQ(x.top_floor, y.top_floor);
        EXPECT_EQ(x.step_observations, y.step_observations);
        EXPECT_EQ(x.stairs.step_height, y.stairs.step_height);
        EXPECT_EQ(x.stairs.step_depth, y.stairs.step_depth);
        EXPECT_EQ(x.stairs.step_width, y.stairs.step_width);
        EXPECT_EQ(x.stairs.slope_rad, y.stairs.slope_rad);
        EXPECT_EQ(x.stairs.heading_rad, y.stairs.heading_rad);
        EXPECT_EQ(x.stairs.location, y.stairs.location);
        EXPECT_EQ(x.stairs.left_side, y.stairs.left_side);
        EXPECT_EQ(x.stairs.right_side, y.stairs.right_side);
        ASSERT_EQ(x.stairs.steps.size(), y.stairs.steps.size());
        for (std::size_t k = 0; k < x.stairs.steps.size(); ++k) {
            expectSameEdge(x.stairs.steps[k], y.stairs.steps[k]);
        }
    }
    ASSERT_EQ(a.floor_levels.size(), b.floor_levels.size());
    for (std::size_t i = 0; i < a.floor_levels.size(); ++i) {
        const Floor &x = a.floor_levels[i], &y = b.floor_levels[i];
        EXPECT_EQ(x.id, y.id);
        EXPECT_EQ(x.z, y.z);
        EXPECT_EQ(x.robot_samples, y.robot_samples);
        EXPECT_EQ(x.robot_z_sum, y.robot_z_sum);
        EXPECT_EQ(x.staircase_ends, y.staircase_ends);
        EXPECT_EQ(x.end_z_sum, y.end_z_sum);
    }
    EXPECT_EQ(a.absorbed, b.absorbed);
    EXPECT_EQ(a.next_landmark_id, b.next_landmark_id);
    EXPECT_EQ(a.next_floor_id, b.next_floor_id);
}

TEST(LandmarkJson, TestMapIsRich) {
    // Guards the other tests: the map exercises joins, floors and several landmarks.
    const LandmarkMap map = test::buildTestMap();
    EXPECT_EQ(map.staircases().size(), 3u);
    EXPECT_FALSE(map.state().absorbed.empty());
    EXPECT_EQ(map.floors().size(), 3u);
}

TEST(LandmarkJson, SaveLoadRoundTripIsExact) {
    const std::string path = test::scratchDir("roundtrip") + "/landmarks.json";
    const LandmarkMap map = test::buildTestMap();
    io::saveLandmarkMapAtomic(path, map);
    const LandmarkMap loaded = io::loadLandmarkMap(path);
    expectSameState(map.state(), loaded.state());
    EXPECT_EQ(loaded.params().use_footprint, false);  // stored params came back
    const std::string again = path + ".again";
    io::saveLandmarkMapAtomic(again, loaded);
    EXPECT_EQ(test::readFile(path), test::readFile(again));
}

TEST(LandmarkJson, RequiredPlannerFieldsArePresent) {
    const LandmarkMap map = test::buildTestMap();
    const nlohmann::json doc = io::landmarkStateToJson(map.state(), map.params());
    EXPECT_EQ(doc.at("version"), 1);
    EXPECT_EQ(doc.at("frame"), "world");
    ASSERT_EQ(doc.at("floors").size(), 3u);
    EXPECT_NEAR(doc["floors"][1]["z"].get<double>(), test::buildingFlights()[0].topZ(), 0.02);
    const nlohmann::json& s = doc.at("staircases").at(0);
    EXPECT_EQ(s.at("num_steps"), s.at("steps").size());
    const test::FlightTruth truth = test::buildingFlights()[0];
    EXPECT_NEAR(s.at("step_height").get<double>(), truth.rise, 0.01);
    EXPECT_NEAR(s.at("step_depth").get<double>(), truth.run, 0.015);
    EXPECT_NEAR(s.at("step_width").get<double>(), truth.width, 0.1);
    EXPECT_NEAR(s.at("heading_deg").get<double>(), truth.heading_rad * 180 / M_PI, 1.0);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(s.at("location")[i].get<double>(), truth.edgeCentre(0)[i], 0.03);
    }
    EXPECT_EQ(s.at("bottom_floor"), doc["floors"][0]["id"]);
    EXPECT_EQ(s.at("top_floor"), doc["floors"][1]["id"]);
}

TEST(LandmarkJson, LoadingWithCurrentParamsReconfirms) {
    const std::string path = test::scratchDir("reconfirm") + "/landmarks.json";
    io::saveLandmarkMapAtomic(path, test::buildTestMap());
    LandmarkParams strict;
    strict.confirm_observations = 100;
    const LandmarkMap loaded = io::loadLandmarkMap(path, strict);
    for (const StaircaseLandmark& lm : loaded.staircases()) EXPECT_FALSE(lm.confirmed);
}

TEST(LandmarkJson, ContinuationKeepsIdsAndSecondRobotMergesIn) {
    const std::string path = test::scratchDir("continuation") + "/landmarks.json";
    LandmarkMap first;
    const std::vector<Staircase> run1 = test::robotDetections(7);
    for (std::size_t i = 0; i < run1.size(); ++i) first.addDetection(run1[i], i);
    ASSERT_EQ(first.staircases().size(), 3u);
    io::saveLandmarkMapAtomic(path, first);

    LandmarkMap second = io::loadLandmarkMap(path, LandmarkParams{});
    for (std::size_t i = 0; i < run1.size(); ++i) {
        const LandmarkUpdate u = second.addDetection(run1[i], 100 + i);
        EXPECT_FALSE(u.created);
        EXPECT_EQ(u.landmark_id, first.addDetection(run1[i], 100 + i).landmark_id);
    }
    for (const Staircase& d : test::robotDetections(8, true)) {
        const LandmarkUpdate u = second.addDetection(d, 200);
        EXPECT_FALSE(u.created);
        EXPECT_TRUE(u.absorbed_ids.empty());
    }
    ASSERT_EQ(second.staircases().size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(second.staircases()[i].id, static_cast<int>(i));
        EXPECT_EQ(second.staircases()[i].observations, 12);
        EXPECT_EQ(second.staircases()[i].stairs.steps.size(), 18u);
    }
}

TEST(LandmarkJson, SidesRoundTripAndMapsWithoutThemStillLoad) {
    const LandmarkMap map = test::buildTestMap();
    LandmarkMapState state = map.state();
    state.staircases.at(0).stairs.left_side = StairSide::Wall;
    state.staircases.at(0).stairs.right_side = StairSide::Open;
    nlohmann::json doc = io::landmarkStateToJson(state, map.params());
    EXPECT_EQ(doc["staircases"][0]["left_side"], "wall");
    EXPECT_EQ(doc["staircases"][0]["right_side"], "open");
    EXPECT_EQ(doc["staircases"][1]["left_side"], "unseen");
    const std::string dir = test::scratchDir("sides");
    {
        std::ofstream(dir + "/with.json") << doc.dump();
    }
    const LandmarkMap with = io::loadLandmarkMap(dir + "/with.json");
    EXPECT_EQ(with.staircases().at(0).stairs.left_side, StairSide::Wall);
    EXPECT_EQ(with.staircases().at(0).stairs.right_side, StairSide::Open);
    for (auto& s : doc["staircases"]) {
        s.erase("left_side");
        s.erase("right_side");
    }
    {
        std::ofstream(dir + "/without.json") << doc.dump();
    }
    const LandmarkMap without = io::loadLandmarkMap(dir + "/without.json");
    ASSERT_EQ(without.staircases().size(), map.staircases().size());
    EXPECT_EQ(without.staircases().at(0).stairs.left_side, StairSide::Unseen);
    EXPECT_EQ(without.staircases().at(0).stairs.step_width, map.staircases().at(0).stairs.step_width);
}

}  // namespace
}  // namespace stairmap
