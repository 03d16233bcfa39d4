// StaircaseJson: the exact `stairmap detect` contract, round trips, and field-naming validation.

#include "io/json/StaircaseJson.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stairmap::io {
namespace {

using nlohmann::json;

/// A 3-step descending staircase with distinct, known numbers in every field.
Staircase knownStaircase() {
    Staircase s;
    s.direction = StairDirection::Descending;
    for (int i = 0; i < 3; ++i) {
        StairEdge e;
        e.start = Eigen::Vector3d(2.0 + 0.3 * i, -0.5, -0.17 * (i + 1));
        e.end = Eigen::Vector3d(2.0 + 0.3 * i, 0.5, -0.17 * (i + 1));
        e.cov_rho_theta << 1e-4 * (i + 1), 2e-6, 2e-6, 3e-5;
        e.num_points = 40 + i;
        s.steps.push_back(e);
    }
    s.step_height = 0.17;
    s.step_depth = 0.30;
    s.step_width = 1.0;
    s.slope_rad = std::atan2(0.17, 0.30);
    s.location = Eigen::Vector3d(2.0, 0.0, -0.17);
    s.heading_rad = -M_PI / 2;
    return s;
}

TEST(StaircaseJson, ToJsonHasEveryContractFieldWithUnits) {
    const json j = toJson(knownStaircase());
    EXPECT_EQ(j.at("direction"), "descending");
    EXPECT_EQ(j.at("num_steps"), 3);
    EXPECT_DOUBLE_EQ(j.at("step_height").get<double>(), 0.17);
    EXPECT_DOUBLE_EQ(j.at("step_depth").get<double>(), 0.30);
    EXPECT_DOUBLE_EQ(j.at("step_width").get<double>(), 1.0);
    EXPECT_NEAR(j.at("slope_deg").get<double>(), std::atan2(0.17, 0.30) * 180.0 / M_PI, 1e-12);
    EXPECT_NEAR(j.at("heading_deg").get<double>(), -90.0, 1e-12);
    EXPECT_EQ(j.at("location"), json({2.0, 0.0, -0.17}));
    ASSERT_EQ(j.at("steps").size(), 3u);
    EXPECT_EQ(j.at("steps")[1].at("start"), json({2.3, -0.5, -0.34}));
    EXPECT_EQ(j.at("steps")[1].at("end"), json({2.3, 0.5, -0.34}));
    EXPECT_EQ(j.at("steps")[2].at("num_points"), 42);
}

TEST(StaircaseJson, AscendingDirectionString) {
    Staircase s = knownStaircase();
    s.direction = StairDirection::Ascending;
    EXPECT_EQ(toJson(s).at("direction"), "ascending");
}

TEST(StaircaseJson, RoundTripThroughTextIsExact) {
    const Staircase s = knownStaircase();
    const Staircase back = staircaseFromJson(json::parse(toJson(s).dump()));
    EXPECT_EQ(back.direction, s.direction);
    EXPECT_DOUBLE_EQ(back.step_height, s.step_height);
    EXPECT_DOUBLE_EQ(back.step_depth, s.step_depth);
    EXPECT_DOUBLE_EQ(back.step_width, s.step_width);
    EXPECT_NEAR(back.slope_rad, s.slope_rad, 1e-12);
    EXPECT_NEAR(back.heading_rad, s.heading_rad, 1e-12);
    EXPECT_EQ(back.location, s.location);
    ASSERT_EQ(back.steps.size(), s.steps.size());
    for (std::size_t i = 0; i < s.steps.size(); ++i) {
        EXPECT_EQ(back.steps[i].start, s.steps[i].start);
        EXPECT_EQ(back.steps[i].end, s.steps[i].end);
        EXPECT_EQ(back.steps[i].num_points, s.steps[i].num_points);
        EXPECT_TRUE(back.steps[i].cov_rho_theta.isApprox(s.steps[i].cov_rho_theta, 1e-15));
    }
}

TEST(StaircaseJson, MinimalContractObjectParses) {
    const json j = json::parse(R"({"direction":"ascending","step_height":0.18,"step_depth":0.28,
        "step_width":0.9,"slope_deg":32.7,"location":[1,0,-0.6],"heading_deg":0,
        "steps":[{"start":[1,-0.45,-0.6],"end":[1,0.45,-0.6]}]})");
    const Staircase s = staircaseFromJson(j);
    EXPECT_EQ(s.direction, StairDirection::Ascending);
    ASSERT_EQ(s.steps.size(), 1u);
    EXPECT_EQ(s.steps[0].end, Eigen::Vector3d(1, 0.45, -0.6));
    EXPECT_NEAR(s.slope_rad, 32.7 * M_PI / 180.0, 1e-12);
}

/// Breaks one field of a valid object and expects the error to name it.
void expectFieldError(const std::function<void(json&)>& breakIt, const std::string& field) {
    json j = toJson(knownStaircase());
    breakIt(j);
    try {
        staircaseFromJson(j);
        ADD_FAILURE() << "accepted a broken " << field;
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(field + ":", 0), 0u) << e.what();
    }
}

TEST(StaircaseJson, ValidationNamesTheBadField) {
    expectFieldError([](json& j) { j["direction"] = "sideways"; }, "staircase.direction");
    expectFieldError([](json& j) { j.erase("step_height"); }, "staircase.step_height");
    expectFieldError([](json& j) { j["step_depth"] = "deep"; }, "staircase.step_depth");
    expectFieldError([](json& j) { j["step_width"] = -1.0; }, "staircase.step_width");
    expectFieldError([](json& j) { j["location"] = json({1, 2}); }, "staircase.location");
    expectFieldError([](json& j) { j["steps"] = 3; }, "staircase.steps");
    expectFieldError([](json& j) { j["steps"][2]["end"][1] = "y"; }, "staircase.steps[2].end[1]");
    expectFieldError([](json& j) { j["steps"][0].erase("start"); }, "staircase.steps[0].start");
    expectFieldError([](json& j) { j["steps"][1]["cov_rho_theta"] = json({1, 2}); },
                     "staircase.steps[1].cov_rho_theta");
    expectFieldError([](json& j) { j["num_steps"] = 5; }, "staircase.num_steps");
    expectFieldError([](json& j) { j = json::array(); }, "staircase");
}

TEST(StaircaseJson, DetectionToJsonIsTheCliContract) {
    DetectionResult result;
    result.staircases = {knownStaircase(), knownStaircase()};
    result.staircases[1].direction = StairDirection::Ascending;
    result.floor_z = -0.55;
    result.floor_estimated = true;
    const json j = detectionToJson(result, 1.25);
    ASSERT_TRUE(j.at("staircases").is_array());
    ASSERT_EQ(j.at("staircases").size(), 2u);
    EXPECT_EQ(j.at("staircases")[0].at("direction"), "descending");
    EXPECT_EQ(j.at("staircases")[1].at("direction"), "ascending");
    EXPECT_DOUBLE_EQ(j.at("time_ms").get<double>(), 1.25);
    EXPECT_DOUBLE_EQ(j.at("floor_z").get<double>(), -0.55);
    EXPECT_EQ(j.at("floor_estimated"), true);
    // start_z: above the floor (-0.55), descending: the first edge's own surface (-0.17);
    // ascending: one rise (0.17) under its first edge.
    EXPECT_NEAR(j.at("staircases")[0].at("start_z").get<double>(), 0.38, 1e-12);
    EXPECT_NEAR(j.at("staircases")[1].at("start_z").get<double>(), 0.21, 1e-12);
    EXPECT_EQ(detectionToJson(DetectionResult{}, 0.0).at("staircases"), json::array());
}

TEST(StaircaseJson, SidesAreWrittenAndReadBack) {
    Staircase s = knownStaircase();
    s.left_side = StairSide::Wall;
    s.right_side = StairSide::Open;
    const json j = toJson(s);
    EXPECT_EQ(j.at("left_side"), "wall");
    EXPECT_EQ(j.at("right_side"), "open");
    const Staircase back = staircaseFromJson(json::parse(j.dump()));
    EXPECT_EQ(back.left_side, StairSide::Wall);
    EXPECT_EQ(back.right_side, StairSide::Open);
    EXPECT_EQ(toJson(knownStaircase()).at("left_side"), "unseen");
}

TEST(StaircaseJson, FilesWithoutSidesLoadAsUnseenAndBadSidesAreNamed) {
    Staircase s = knownStaircase();
    s.left_side = StairSide::Wall;
    json j = toJson(s);
    j.erase("left_side");
    j.erase("right_side");
    const Staircase back = staircaseFromJson(j);
    EXPECT_EQ(back.left_side, StairSide::Unseen);
    EXPECT_EQ(back.right_side, StairSide::Unseen);
    j["right_side"] = "railing";
    try {
        staircaseFromJson(j);
        ADD_FAILURE() << "accepted right_side \"railing\"";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("staircase.right_side"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace stairmap::io
