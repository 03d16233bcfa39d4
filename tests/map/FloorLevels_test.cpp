// Floor levels from where the robot drove and from staircase ends; each staircase links its
// bottom floor to its top floor.
#include <gtest/gtest.h>

#include "map/LandmarkMap.h"
#include "core/SyntheticStairs.h"

namespace stairmap {
namespace {

test::FlightTruth twoFloorFlight() {
    test::FlightTruth t;
    t.num_steps = 18;  // 0 m -> 3.06 m
    t.origin_xy = {1.0, 2.0};
    return t;
}

void observe(LandmarkMap& map, const test::FlightTruth& t, int times, std::mt19937& rng) {
    for (int k = 0; k < times; ++k) {
        test::ViewSpec v;
        v.sigma_perp = 0.01;
        v.sigma_z = 0.01;
        v.descending = (k % 2) == 1;
        map.addDetection(test::makeDetection(t, v, rng), k);
    }
}

const Floor* floorNear(const std::vector<Floor>& floors, double z) {
    for (const Floor& f : floors) {
        if (std::abs(f.z - z) < 0.1) return &f;
    }
    return nullptr;
}

TEST(FloorLevels, TwoFloorsFromRobotHeightsAndStaircaseLinksThem) {
    const test::FlightTruth flight = twoFloorFlight();
    LandmarkMap map;
    std::mt19937 rng(21);
    std::normal_distribution<double> noise(0.0, 0.02);
    for (int i = 0; i < 40; ++i) map.addRobotFloor(0.0 + noise(rng), i);
    for (double z : {0.6, 1.0, 1.5, 2.0, 2.5}) map.addRobotFloor(z, 50);  // while climbing
    for (int i = 0; i < 40; ++i) map.addRobotFloor(flight.topZ() + noise(rng), 60 + i);
    observe(map, flight, 3, rng);

    const std::vector<Floor> floors = map.floors();
    ASSERT_EQ(floors.size(), 2u);
    EXPECT_NEAR(floors[0].z, 0.0, 0.02);
    EXPECT_NEAR(floors[1].z, flight.topZ(), 0.02);
    ASSERT_EQ(map.staircases().size(), 1u);
    EXPECT_EQ(map.staircases()[0].bottom_floor, floors[0].id);
    EXPECT_EQ(map.staircases()[0].top_floor, floors[1].id);
    EXPECT_NE(floors[0].id, floors[1].id);
}

TEST(FloorLevels, ConfirmedStaircaseEndCreatesTheFloorTheRobotNeverDroveOn) {
    const test::FlightTruth flight = twoFloorFlight();
    LandmarkMap map;
    std::mt19937 rng(22);
    for (int i = 0; i < 20; ++i) map.addRobotFloor(0.01, i);
    observe(map, flight, 1, rng);
    // One observation: not confirmed, the top is not (yet) a floor.
    ASSERT_EQ(map.floors().size(), 1u);
    EXPECT_EQ(map.staircases()[0].bottom_floor, map.floors()[0].id);
    EXPECT_EQ(map.staircases()[0].top_floor, -1);
    observe(map, flight, 2, rng);
    const std::vector<Floor> floors = map.floors();
    ASSERT_EQ(floors.size(), 2u);
    const Floor* top = floorNear(floors, flight.topZ());
    ASSERT_NE(top, nullptr);
    EXPECT_EQ(top->robot_samples, 0);
    EXPECT_EQ(map.staircases()[0].top_floor, top->id);
}

TEST(FloorLevels, UnobservedTopOfAPartlySeenFlightCreatesNoFloor) {
    // Only seen from the bottom, and only its lower half: its last edge is not a floor.
    const test::FlightTruth flight = twoFloorFlight();
    LandmarkMap map;
    std::mt19937 rng(24);
    for (int i = 0; i < 20; ++i) map.addRobotFloor(0.0, i);
    for (int k = 0; k < 4; ++k) {
        test::ViewSpec v;
        v.last = 8;
        map.addDetection(test::makeDetection(flight, v, rng), k);
    }
    ASSERT_TRUE(map.staircases()[0].confirmed);
    EXPECT_TRUE(map.staircases()[0].bottom_observed);
    EXPECT_FALSE(map.staircases()[0].top_observed);
    ASSERT_EQ(map.floors().size(), 1u);
    EXPECT_EQ(map.staircases()[0].bottom_floor, map.floors()[0].id);
    EXPECT_EQ(map.staircases()[0].top_floor, -1);
    // Seen once from the top (the whole flight): the upper floor appears.
    test::ViewSpec from_top;
    from_top.descending = true;
    map.addDetection(test::makeDetection(flight, from_top, rng), 5);
    ASSERT_EQ(map.floors().size(), 2u);
    EXPECT_NEAR(map.floors()[1].z, flight.topZ(), 0.01);
    EXPECT_EQ(map.staircases()[0].top_floor, map.floors()[1].id);
}

TEST(FloorLevels, StackedFlightsFormAThreeFloorGraph) {
    test::FlightTruth lower = twoFloorFlight();
    test::FlightTruth upper = lower;
    upper.floor_z = lower.topZ();
    LandmarkMap map;
    std::mt19937 rng(23);
    for (double z : {0.0, lower.topZ(), upper.topZ()}) {
        for (int i = 0; i < 15; ++i) map.addRobotFloor(z, i);
    }
    observe(map, lower, 3, rng);
    observe(map, upper, 3, rng);
    const std::vector<Floor> floors = map.floors();
    ASSERT_EQ(floors.size(), 3u);
    ASSERT_EQ(map.staircases().size(), 2u);
    EXPECT_EQ(map.staircases()[0].bottom_floor, floors[0].id);
    EXPECT_EQ(map.staircases()[0].top_floor, floors[1].id);
    EXPECT_EQ(map.staircases()[1].bottom_floor, floors[1].id);
    EXPECT_EQ(map.staircases()[1].top_floor, floors[2].id);
}

TEST(FloorLevels, FloorIsReportedOnceEnoughRobotSamplesArrive) {
    LandmarkParams params;
    params.floor_min_robot_samples = 5;
    LandmarkMap map(params);
    for (int i = 0; i < 4; ++i) EXPECT_FALSE(map.addRobotFloor(1.0, i));
    EXPECT_TRUE(map.floors().empty());
    EXPECT_TRUE(map.addRobotFloor(1.0, 5));
    ASSERT_EQ(map.floors().size(), 1u);
    EXPECT_DOUBLE_EQ(map.floors()[0].z, 1.0);
    EXPECT_FALSE(map.addRobotFloor(std::nan(""), 6));
}

}  // namespace
}  // namespace stairmap
