// Fusing aligned maps: first map's IDs kept, one landmark per staircase, provenance per landmark
// and per step, floors merged across maps.
#include <gtest/gtest.h>

#include "fleet/MapFusion.h"
#include "map/LandmarkMap.h"
#include "FleetTestMaps.h"

namespace stairmap::fleet::test {
namespace {

FlightSpec flight(int first_level, int last_level) {
    FlightSpec f;
    f.foot = {2.0, 0.8};
    f.first_level = first_level;
    f.last_level = last_level;
    return f;
}

Floor robotFloor(int id, double z, int samples) {
    Floor f;
    f.id = id;
    f.z = z;
    f.robot_samples = samples;
    f.robot_z_sum = z * samples;
    return f;
}

TEST(MapFusion, SharedFlightBecomesOneLandmarkWithProvenanceFromBoth) {
    const Transform4 T{4.0, -3.0, 1.2, 2.0};
    LandmarkMapState first = makeMap({makeLandmark(flight(1, 8), 5)});  // id 5 must survive
    first.floor_levels.push_back(robotFloor(0, 0.0, 10));
    first.next_floor_id = 1;
    FlightSpec far = flight(1, 6);  // a second flight only the other robot saw
    far.foot = {10.0, 10.0};
    far.heading_deg = 90.0;
    LandmarkMapState other_world = makeMap({makeLandmark(flight(5, 12), 0), makeLandmark(far, 1)});
    other_world.floor_levels.push_back(robotFloor(0, 0.02, 6));  // same floor, 2 cm off
    other_world.floor_levels.push_back(robotFloor(1, 3.0, 8));   // a floor only it visited
    other_world.next_floor_id = 2;

    MapFusion fusion(first, LandmarkParams{});
    EXPECT_EQ(fusion.add(inOtherFrame(other_world, T), T), 1);
    const LandmarkMapState& fused = fusion.state();
    ASSERT_EQ(fused.staircases.size(), 2u);
    const StaircaseLandmark& shared = fused.staircases[0];
    EXPECT_EQ(shared.id, 5);
    EXPECT_EQ(shared.stairs.steps.size(), 12u);  // levels 1..8 and 5..12
    EXPECT_EQ(shared.observations, 6);
    EXPECT_NEAR(shared.stairs.steps.front().centre().z(), 0.18, 0.005);
    EXPECT_NEAR(shared.stairs.steps.back().centre().z(), 12 * 0.18, 0.005);
    EXPECT_EQ(fused.staircases[1].id, 6);  // new landmark, new id
    EXPECT_NEAR(fused.staircases[1].stairs.location.x(), 10.0, 0.01);

    const auto prov = fusion.provenance();
    ASSERT_EQ(prov.size(), 2u);
    ASSERT_EQ(prov[0].sources.size(), 2u);
    EXPECT_EQ(prov[0].sources[0].map, 0);
    EXPECT_EQ(prov[0].sources[0].source_id, 5);
    EXPECT_EQ(prov[0].sources[1].map, 1);
    EXPECT_EQ(prov[0].sources[1].source_id, 0);
    ASSERT_EQ(prov[0].steps.size(), 12u);
    EXPECT_EQ(prov[0].steps[0].size(), 1u);   // level 1: first map only
    EXPECT_EQ(prov[0].steps[5].size(), 2u);   // level 6: both
    EXPECT_EQ(prov[0].steps[11].size(), 1u);  // level 12: other map only
    EXPECT_EQ(prov[0].steps[11][0].map, 1);
    EXPECT_EQ(prov[0].steps[5][1].observations, 2);
    ASSERT_EQ(prov[1].sources.size(), 1u);
    EXPECT_EQ(prov[1].sources[0].map, 1);

    // Floors: z = 0 (both robots, merged into floor 0) and z = 3 (the other robot only).
    LandmarkMap check(fused, LandmarkParams{});
    const auto floors = check.floors();
    ASSERT_EQ(floors.size(), 2u);
    EXPECT_EQ(floors[0].id, 0);
    EXPECT_EQ(floors[0].robot_samples, 16);
    EXPECT_NEAR(floors[1].z, 3.0, 1e-9);
}

TEST(MapFusion, EmptyMapsFuseToTheFirst) {
    MapFusion fusion(LandmarkMapState{}, LandmarkParams{});
    fusion.add(LandmarkMapState{}, Transform4{});
    EXPECT_TRUE(fusion.state().staircases.empty());
    EXPECT_TRUE(fusion.provenance().empty());
}

}  // namespace
}  // namespace stairmap::fleet::test
