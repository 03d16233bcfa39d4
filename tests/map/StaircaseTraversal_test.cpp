// A flight the robot climbed through is linked to the floors at both ends of the climb, even when
// the detector saw only its lower part (map/StaircaseTraversal.h, docs/landmarks.md "Floors").
#include <gtest/gtest.h>

#include <random>

#include "io/json/LandmarkJson.h"
#include "LandmarkTestMaps.h"
#include "map/LandmarkMap.h"
#include "core/StaircaseCanonical.h"
#include "map/StaircaseTraversal.h"
#include "core/SyntheticStairs.h"

namespace stairmap {
namespace {

test::FlightTruth flight() {
    test::FlightTruth t;
    t.num_steps = 18;  // 0 m -> 3.06 m
    t.origin_xy = {1.0, 2.0};
    t.heading_rad = 0.4;
    return t;
}

/// Floor under a robot walking up the middle of `t` (shifted sideways by `side` [m]) from `before`
/// metres ahead of the lowest nosing to `after` metres beyond the top one, one sample every
/// 0.35 m, with seeded noise. Heights follow the treads: tread k (from the lowest nosing) is at
/// floor + (k + 1) rise; before the flight the bottom floor, beyond it the top floor.
FloorTransit climb(const test::FlightTruth& t, std::mt19937& rng, double side = 0.0,
                   bool descend = false) {
    std::normal_distribution<double> noise(0.0, 0.03);
    const double before = -1.0, top_along = (t.num_steps - 1) * t.run, after = top_along + 1.0;
    FloorTransit transit;
    for (double along = before; along <= after + 1e-9; along += 0.35) {
        const double level = std::clamp(std::floor(along / t.run) + 1.0, 0.0, double(t.num_steps));
        const bool on_level_ground = along == before || along + 0.35 > after + 1e-9;
        const double z = t.floor_z + level * t.rise + (on_level_ground ? 0.0 : noise(rng));
        const Eigen::Vector2d xy = t.origin_xy + along * t.uphill() + side * t.left() +
                                   Eigen::Vector2d(noise(rng), noise(rng));
        transit.floor_path.emplace_back(xy.x(), xy.y(), z);
    }
    if (descend) std::reverse(transit.floor_path.begin(), transit.floor_path.end());
    transit.stamp_s = 100.0;
    return transit;
}

/// A map with both floors driven on and the flight seen only from below, up to its 7th nosing,
/// so that its top is 1.9 m below the upper floor.
LandmarkMap partlySeenFlight(std::mt19937& rng) {
    const test::FlightTruth t = flight();
    LandmarkMap map;
    for (int i = 0; i < 20; ++i) map.addRobotFloor(0.0, i);
    for (int i = 0; i < 20; ++i) map.addRobotFloor(t.topZ(), 20 + i);
    for (int k = 0; k < 3; ++k) {
        test::ViewSpec v;
        v.last = 6;
        v.sigma_perp = 0.01;
        v.sigma_z = 0.005;
        map.addDetection(test::makeDetection(t, v, rng), 50 + k);
    }
    return map;
}

TEST(StaircaseTraversal, ClimbLinksAPartlySeenFlightToItsTopFloor) {
    std::mt19937 rng(31);
    LandmarkMap map = partlySeenFlight(rng);
    const std::vector<Floor> floors = map.floors();
    ASSERT_EQ(floors.size(), 2u);
    ASSERT_EQ(map.staircases().size(), 1u);
    EXPECT_EQ(map.staircases()[0].bottom_floor, floors[0].id);
    EXPECT_EQ(map.staircases()[0].top_floor, -1);  // without the climb the top is unknown
    EXPECT_TRUE(map.addFloorTransit(climb(flight(), rng)));
    EXPECT_EQ(map.staircases()[0].bottom_floor, floors[0].id);
    EXPECT_EQ(map.staircases()[0].top_floor, floors[1].id);
    EXPECT_EQ(map.floors().size(), 2u);  // no floor invented
}

TEST(StaircaseTraversal, DescentLinksToo) {
    std::mt19937 rng(32);
    LandmarkMap map = partlySeenFlight(rng);
    map.addFloorTransit(climb(flight(), rng, 0.0, true));
    EXPECT_EQ(map.staircases()[0].bottom_floor, map.floors()[0].id);
    EXPECT_EQ(map.staircases()[0].top_floor, map.floors()[1].id);
}

TEST(StaircaseTraversal, ClimbBeforeTheFlightWasDetectedStillLinks) {
    std::mt19937 rng(33);
    const test::FlightTruth t = flight();
    LandmarkMap map;
    for (int i = 0; i < 20; ++i) map.addRobotFloor(0.0, i);
    for (int i = 0; i < 20; ++i) map.addRobotFloor(t.topZ(), 20 + i);
    map.addFloorTransit(climb(t, rng));
    EXPECT_TRUE(map.staircases().empty());
    test::ViewSpec v;
    v.last = 5;
    map.addDetection(test::makeDetection(t, v, rng), 60);
    ASSERT_EQ(map.staircases().size(), 1u);
    EXPECT_EQ(map.staircases()[0].top_floor, map.floors()[1].id);
}

TEST(StaircaseTraversal, ClimbElsewhereDoesNotLink) {
    std::mt19937 rng(34);
    LandmarkMap map = partlySeenFlight(rng);
    // A parallel flight 3 m to the left (e.g. the next stairwell) and a climb through it.
    EXPECT_FALSE(map.addFloorTransit(climb(flight(), rng, 3.0)));
    EXPECT_EQ(map.staircases()[0].top_floor, -1);
}

TEST(StaircaseTraversal, ClimbAgainstTheHeadingDoesNotLink) {
    // Rising while walking downhill along the flight cannot be a climb of this flight.
    std::mt19937 rng(35);
    const test::FlightTruth t = flight();
    const Staircase s = *canonicalStaircase(test::makeDetection(t, test::ViewSpec{}, rng));
    FloorTransit transit = climb(t, rng);
    ASSERT_TRUE(traversedFloors(s, transit, LandmarkParams{}).has_value());
    const Eigen::Vector3d low = transit.floor_path.front(), high = transit.floor_path.back();
    for (Eigen::Vector3d& p : transit.floor_path) p.head<2>() = low.head<2>() + high.head<2>() - p.head<2>();
    EXPECT_FALSE(traversedFloors(s, transit, LandmarkParams{}).has_value());
}

TEST(StaircaseTraversal, TraversedFloorsAreTheClimbEnds) {
    std::mt19937 rng(36);
    const test::FlightTruth t = flight();
    const Staircase s = *canonicalStaircase(test::makeDetection(t, test::ViewSpec{}, rng));
    const std::optional<TraversedFloors> f = traversedFloors(s, climb(t, rng), LandmarkParams{});
    ASSERT_TRUE(f.has_value());
    EXPECT_NEAR(f->low_z, 0.0, 1e-9);
    EXPECT_NEAR(f->high_z, t.topZ(), 1e-9);
}

TEST(StaircaseTraversal, ClimbHigherThanOneFlightCanRiseDoesNotLink) {
    // Two stacked flights climbed at once: 6.1 m exceeds the building code's flight rise.
    std::mt19937 rng(37);
    test::FlightTruth tall = flight();
    tall.num_steps = 36;
    const Staircase s = *canonicalStaircase(test::makeDetection(tall, test::ViewSpec{}, rng));
    EXPECT_FALSE(traversedFloors(s, climb(tall, rng), LandmarkParams{}).has_value());
    LandmarkParams lenient;
    lenient.max_flight_rise_m = 7.0;
    EXPECT_TRUE(traversedFloors(s, climb(tall, rng), lenient).has_value());
}

TEST(StaircaseTraversal, TransitsSurviveSaveAndLoad) {
    std::mt19937 rng(38);
    LandmarkMap map = partlySeenFlight(rng);
    const FloorTransit transit = climb(flight(), rng);
    map.addFloorTransit(transit);
    const std::string path = test::scratchDir("transits") + "/landmarks.json";
    io::saveLandmarkMapAtomic(path, map);
    const LandmarkMap loaded = io::loadLandmarkMap(path);
    ASSERT_EQ(loaded.state().transits.size(), 1u);
    EXPECT_EQ(loaded.state().transits[0].floor_path, transit.floor_path);
    EXPECT_EQ(loaded.state().transits[0].stamp_s, transit.stamp_s);
    EXPECT_EQ(loaded.staircases()[0].top_floor, map.staircases()[0].top_floor);
    EXPECT_NE(loaded.staircases()[0].top_floor, -1);
}

TEST(StaircaseTraversal, OnlyTheLatestTransitsAreKept) {
    std::mt19937 rng(41);
    LandmarkMap map;
    for (int i = 0; i < 300; ++i) {
        FloorTransit t = climb(flight(), rng);
        t.stamp_s = i;
        map.addFloorTransit(t);
    }
    ASSERT_EQ(map.state().transits.size(), 256u);
    EXPECT_EQ(map.state().transits.front().stamp_s, 44.0);
    EXPECT_EQ(map.state().transits.back().stamp_s, 299.0);
}

TEST(StaircaseTraversal, DocumentWithoutTransitsStillLoads) {
    // Version-1 documents written before transits existed have no "transits" member.
    std::mt19937 rng(39);
    LandmarkMap map = partlySeenFlight(rng);
    nlohmann::json doc = io::landmarkStateToJson(map.state(), map.params());
    doc["continuation"].erase("transits");
    const LandmarkMapState state = io::landmarkStateFromJson(doc);
    EXPECT_TRUE(state.transits.empty());
    EXPECT_EQ(state.staircases.size(), 1u);
}

TEST(StaircaseTraversal, CorruptTransitIsReported) {
    std::mt19937 rng(40);
    LandmarkMap map = partlySeenFlight(rng);
    map.addFloorTransit(climb(flight(), rng));
    nlohmann::json doc = io::landmarkStateToJson(map.state(), map.params());
    doc["continuation"]["transits"][0]["floor_path"][1] = {1.0, "x", 2.0};
    try {
        io::landmarkStateFromJson(doc);
        FAIL() << "corrupt transit accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("continuation.transits[0].floor_path[1]"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace stairmap
