// The landmark map on the bundled simulated buildings (datasets/*/gt.json): noisy partial
// detections of the ground-truth flights, ascending and descending, from one robot or two, give
// exactly the building's staircases on the right floors with rise/run/width within 1/1.5/10 cm.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "io/json/LandmarkJson.h"
#include "LandmarkTestMaps.h"

namespace stairmap {
namespace {

struct Building {
    std::vector<test::FlightTruth> flights;
    std::vector<double> floor_heights;
};

Eigen::Vector3d point(const nlohmann::json& j) {
    return Eigen::Vector3d(j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>());
}

/// The gt flights are straight: rebuild each as a FlightTruth from its nosings.
Building loadBuilding(const std::string& dataset) {
    std::ifstream in(std::string(STAIRMAP_SOURCE_DIR) + "/datasets/" + dataset + "/gt.json");
    EXPECT_TRUE(in.good()) << dataset;
    const nlohmann::json gt = nlohmann::json::parse(in);
    Building b;
    b.floor_heights = gt.at("floor_heights").get<std::vector<double>>();
    for (const nlohmann::json& s : gt.at("staircases")) {
        const nlohmann::json& n = s.at("nosings");
        const Eigen::Vector3d c0 = 0.5 * (point(n[0]["start"]) + point(n[0]["end"]));
        const Eigen::Vector3d c1 = 0.5 * (point(n[1]["start"]) + point(n[1]["end"]));
        test::FlightTruth f;
        f.origin_xy = c0.head<2>();
        f.floor_z = s.at("bottom_z");
        f.heading_rad = std::atan2(c1.y() - c0.y(), c1.x() - c0.x());
        f.rise = s.at("rise_m");
        f.run = s.at("run_m");
        f.width = s.at("width_m");
        f.num_steps = static_cast<int>(n.size());
        EXPECT_NEAR(f.topZ(), s.at("top_z").get<double>(), 1e-6);
        b.flights.push_back(f);
    }
    return b;
}

/// Partial views as a robot sees them while driving past: from the bottom, from the top, with
/// pose drift of a few cm.
std::vector<Staircase> detections(const Building& b, unsigned seed, int views) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> drift(-0.03, 0.03);
    std::vector<Staircase> out;
    for (int k = 0; k < views; ++k) {
        for (const test::FlightTruth& f : b.flights) {
            test::ViewSpec v;
            v.descending = (k % 2) == 1;
            const int seen = 4 + k % 4;
            v.first = v.descending ? f.num_steps - seen : 0;
            v.last = v.descending ? f.num_steps - 1 : seen - 1;
            v.drift = {drift(rng), drift(rng), drift(rng) / 3};
            v.sigma_perp = 0.01;
            v.sigma_theta = 0.01;
            v.sigma_z = 0.008;
            v.sigma_end = 0.02;
            out.push_back(test::makeDetection(f, v, rng));
        }
    }
    return out;
}

/// Nosings the views of detections() show: ascending views the lowest 4 or 6, descending views
/// the highest 5 or 7.
int seenSteps(int num_steps) { return std::min(num_steps, 6 + 7); }

void addRobotFloors(LandmarkMap& map, const Building& b) {
    for (const double z : b.floor_heights) {
        for (int i = 0; i < 8; ++i) map.addRobotFloor(z + 0.005 * (i % 3), i);
    }
}

void expectMatchesBuilding(const LandmarkMap& map, const Building& b) {
    ASSERT_EQ(map.staircases().size(), b.flights.size());
    const std::vector<Floor> floors = map.floors();
    ASSERT_EQ(floors.size(), b.floor_heights.size());
    for (std::size_t i = 0; i < floors.size(); ++i) EXPECT_NEAR(floors[i].z, b.floor_heights[i], 0.05);
    for (std::size_t i = 0; i < b.flights.size(); ++i) {
        const test::FlightTruth& f = b.flights[i];
        const StaircaseLandmark& lm = map.staircases()[i];
        const Staircase& s = lm.stairs;
        SCOPED_TRACE("staircase " + std::to_string(lm.id));
        EXPECT_TRUE(lm.confirmed);
        EXPECT_NEAR(s.step_height, f.rise, 0.01);
        EXPECT_NEAR(s.step_depth, f.run, 0.015);
        EXPECT_NEAR(s.step_width, f.width, 0.10);
        EXPECT_LT((s.location - f.edgeCentre(0)).norm(), 0.05);
        // Every fused edge sits on a true nosing, one edge per nosing seen.
        EXPECT_EQ(static_cast<int>(s.steps.size()), seenSteps(f.num_steps));
        for (const StairEdge& e : s.steps) {
            const double level = (e.centre().z() - f.floor_z) / f.rise - 1.0;
            EXPECT_NEAR(level, std::round(level), 0.1);
        }
        std::printf("gt flight %zu: rise %.4f (gt %.4f) run %.4f (gt %.4f) width %.3f (gt %.3f)\n",
                    i, s.step_height, f.rise, s.step_depth, f.run, s.step_width, f.width);
        ASSERT_GE(lm.bottom_floor, 0);
        ASSERT_GE(lm.top_floor, 0);
        for (const Floor& fl : floors) {
            if (fl.id == lm.bottom_floor) {
                EXPECT_NEAR(fl.z, f.floor_z, 0.05);
            }
            if (fl.id == lm.top_floor) {
                EXPECT_NEAR(fl.z, f.topZ(), 0.05);
            }
        }
    }
}

TEST(LandmarkGroundTruth, TwoFloorBuildingGivesItsStaircasesOnTheRightFloors) {
    const Building b = loadBuilding("two_floor");
    ASSERT_EQ(b.flights.size(), 2u);
    LandmarkMap map;
    addRobotFloors(map, b);
    for (const Staircase& d : detections(b, 51, 8)) map.addDetection(d, 0.0);
    expectMatchesBuilding(map, b);
}

TEST(LandmarkGroundTruth, SecondRobotAndSecondRunMergeIntoTheSameLandmarks) {
    const Building b = loadBuilding("two_robot");
    const std::string path = test::scratchDir("two_robot") + "/landmarks.json";
    LandmarkMap robot_a;
    addRobotFloors(robot_a, b);
    const std::vector<Staircase> run_a = detections(b, 61, 6);
    for (const Staircase& d : run_a) robot_a.addDetection(d, 1.0);
    io::saveLandmarkMapAtomic(path, robot_a);

    LandmarkMap robot_b = io::loadLandmarkMap(path, LandmarkParams{});
    for (const Staircase& d : detections(b, 62, 6)) {
        EXPECT_FALSE(robot_b.addDetection(d, 2.0).created);
    }
    for (const Staircase& d : run_a) EXPECT_FALSE(robot_b.addDetection(d, 3.0).created);
    expectMatchesBuilding(robot_b, b);
    for (std::size_t i = 0; i < robot_a.staircases().size(); ++i) {
        EXPECT_EQ(robot_b.staircases()[i].id, robot_a.staircases()[i].id);
    }
}

}  // namespace
}  // namespace stairmap
