// The live fleet map on synthetic maps with known transforms: alignment recovered, one landmark
// per staircase, silent robots keep their landmarks, late first robot, unalignable robot.
#include <gtest/gtest.h>

#include <set>

#include "fleetlive/FleetScenario.h"
#include "fleetlive/LiveFleetMap.h"

namespace stairmap::fleetlive::test {
namespace {

class FleetTransforms : public ::testing::TestWithParam<Transform4> {};

TEST_P(FleetTransforms, OneLandmarkPerStaircaseAndTheTransformRecovered) {
    const Transform4 T = GetParam();
    LiveFleetMap fleet(2);
    fleet.update(0, robotA());
    fleet.update(1, robotB(T));
    EXPECT_EQ(fleet.fleetMap().staircases.size(), 4u);  // 3 shared + B's own
    const RobotStatus& b = fleet.status()[1];
    ASSERT_TRUE(b.in_fleet_map) << b.note;
    ASSERT_TRUE(b.T_fleet_robot.has_value());
    EXPECT_NEAR(b.T_fleet_robot->x, T.x, 0.05);
    EXPECT_NEAR(b.T_fleet_robot->y, T.y, 0.05);
    EXPECT_NEAR(b.T_fleet_robot->z, T.z, 0.05);
    EXPECT_LT(fleet::test::yawErrorDeg(b.T_fleet_robot->yaw_rad, T.yaw_rad), 1.0);
    // B's own flight lands where it is in A's frame
    const LandmarkMapState truth = mapOf({onlyB()});
    bool found = false;
    for (const StaircaseLandmark& l : fleet.fleetMap().staircases)
        found |= (l.stairs.location - truth.staircases[0].stairs.location).norm() < 0.05;
    EXPECT_TRUE(found);
}

INSTANTIATE_TEST_SUITE_P(Transforms, FleetTransforms,
                         ::testing::Values(Transform4{0, 0, 0, 0}, Transform4{3.0, -2.0, 0.0, 0.7},
                                           Transform4{-12.0, 5.0, 2.8, -2.5}, Transform4{0.5, 40.0, -3.0, 3.1}));

TEST(LiveFleetMap, SilentRobotKeepsItsLandmarksWhenOthersUpdate) {
    const Transform4 T{4.0, 1.0, 0.0, 1.2};
    LiveFleetMap fleet(2);
    fleet.update(0, robotA());
    fleet.update(1, robotB(T));
    ASSERT_EQ(fleet.fleetMap().staircases.size(), 4u);
    fleet.update(0, robotA(true));  // A finds another flight; B says nothing more
    EXPECT_EQ(fleet.fleetMap().staircases.size(), 5u);
    EXPECT_TRUE(fleet.status()[1].in_fleet_map);
}

TEST(LiveFleetMap, RobotsWaitForTheFirstAndForASharedStaircase) {
    const Transform4 T{4.0, 1.0, 0.0, 1.2};
    LiveFleetMap fleet(3);
    fleet.update(1, robotB(T));
    EXPECT_TRUE(fleet.fleetMap().staircases.empty());
    EXPECT_NE(fleet.status()[1].note.find("first robot"), std::string::npos);
    fleet.update(2, mapOf({onlyA()}));  // shares nothing with A's first map
    fleet.update(0, robotA());
    EXPECT_EQ(fleet.fleetMap().staircases.size(), 4u);
    EXPECT_TRUE(fleet.status()[1].in_fleet_map);
    EXPECT_FALSE(fleet.status()[2].in_fleet_map);
    EXPECT_NE(fleet.status()[2].note.find("not aligned"), std::string::npos) << fleet.status()[2].note;
    // once A has seen that flight too, robot 2 joins (and adds nothing new)
    fleet.update(0, robotA(true));
    EXPECT_TRUE(fleet.status()[2].in_fleet_map) << fleet.status()[2].note;
    EXPECT_EQ(fleet.fleetMap().staircases.size(), 5u);
}

TEST(LiveFleetMap, ProvenanceNamesRobotsEvenWhenOneWaitsOutside) {
    const Transform4 T{4.0, 1.0, 0.0, 1.2};
    LiveFleetMap fleet(3);
    fleet.update(0, robotA());
    fleet.update(1, mapOf({onlyA()}));  // not aligned: fused second would be map 1 of the fusion
    fleet.update(2, robotB(T));
    ASSERT_FALSE(fleet.status()[1].in_fleet_map);
    ASSERT_TRUE(fleet.status()[2].in_fleet_map);
    EXPECT_EQ(fleet.status()[2].pairs.size(), sharedFlights().size());
    EXPECT_GT(fleet.status()[2].sigma.xy_m, 0.0);
    ASSERT_EQ(fleet.provenance().size(), fleet.fleetMap().staircases.size());
    int from_both = 0;
    for (const fleet::LandmarkProvenance& p : fleet.provenance()) {
        std::set<int> robots;
        for (const fleet::Contribution& c : p.sources) robots.insert(c.map);
        EXPECT_EQ(robots.count(1), 0u);  // the robot outside contributes nothing
        from_both += robots.count(0) && robots.count(2);
        for (const auto& step : p.steps)
            for (const fleet::Contribution& c : step) EXPECT_NE(c.map, 1);
    }
    EXPECT_EQ(from_both, static_cast<int>(sharedFlights().size()));
}

TEST(LiveFleetMap, BadInputChangesNothing) {
    LiveFleetMap fleet(1);
    EXPECT_THROW(fleet.update(3, robotA()), std::out_of_range);
    LandmarkMapState broken = robotA();
    broken.staircases[1].id = broken.staircases[0].id;  // duplicate ids
    EXPECT_THROW(fleet.update(0, broken), std::invalid_argument);
    EXPECT_FALSE(fleet.status()[0].has_map);
}

}  // namespace
}  // namespace stairmap::fleetlive::test
