// The mapper's record of climbs between floor levels, fed by the level guard as in Mapper.
#include "pipeline/TransitRecorder.h"

#include <gtest/gtest.h>

#include "pipeline/LevelGuard.h"

namespace stairmap::pipeline {
namespace {

/// Feeds a floor path (robot z = floor z + 0.35) through a level guard into the recorder, as the
/// mapper does, and returns the transits it finished.
std::vector<FloorTransit> drive(const std::vector<Eigen::Vector3d>& floor_path) {
    LevelGuard guard(10.0);
    TransitRecorder recorder(0.4);
    std::vector<FloorTransit> out;
    double t = 0.0;
    for (const Eigen::Vector3d& p : floor_path) {
        const bool level = guard.update(p + Eigen::Vector3d(0, 0, 0.35));
        if (auto transit = recorder.update(p, level, t)) out.push_back(*transit);
        t += 0.1;
    }
    return out;
}

/// 2 m of floor at z0, a straight flight (rise 0.17 / run 0.28, 18 steps) up or down along x, and
/// 2 m of floor at the other end; one sample every 0.1 m.
std::vector<Eigen::Vector3d> flightWalk(bool up) {
    std::vector<Eigen::Vector3d> path;
    for (int i = 0; i <= 20; ++i) path.emplace_back(0.1 * i, 0.0, 0.0);
    for (int i = 1; i <= 50; ++i) path.emplace_back(2.0 + 0.1 * i, 0.0, 0.17 / 0.28 * 0.1 * i);
    const double top = path.back().z(), x_top = path.back().x();
    for (int i = 1; i <= 20; ++i) path.emplace_back(x_top + 0.1 * i, 0.0, top);
    if (!up) std::reverse(path.begin(), path.end());
    return path;
}

TEST(TransitRecorder, ClimbGivesOneTransitFromFloorToFloor) {
    const std::vector<Eigen::Vector3d> path = flightWalk(true);
    const std::vector<FloorTransit> transits = drive(path);
    ASSERT_EQ(transits.size(), 1u);
    const FloorTransit& t = transits[0];
    ASSERT_GE(t.floor_path.size(), 10u);  // samples along the flight, not just the ends
    // Starts where the guard last saw level ground (a step or so up, the guard needs 0.6 m of path).
    EXPECT_NEAR(t.floor_path.front().z(), 0.0, 0.15);
    EXPECT_NEAR(t.floor_path.back().z(), path.back().z(), 1e-9);  // ends on the upper floor
    EXPECT_LT(t.floor_path.front().x(), 2.3);  // from where the robot left level ground
    for (std::size_t i = 1; i < t.floor_path.size(); ++i) {
        EXPECT_GE(t.floor_path[i].z(), t.floor_path[i - 1].z());  // in order
    }
}

TEST(TransitRecorder, DescentGivesOneTransitDownwards) {
    const std::vector<FloorTransit> transits = drive(flightWalk(false));
    ASSERT_EQ(transits.size(), 1u);
    EXPECT_NEAR(transits[0].floor_path.front().z(), flightWalk(true).back().z(), 0.15);
    EXPECT_NEAR(transits[0].floor_path.back().z(), 0.0, 1e-9);
}

TEST(TransitRecorder, ShortRampIsNoTransit) {
    // A 30 cm step up over a short steep ramp: below the floor tolerance, not another floor.
    std::vector<Eigen::Vector3d> path;
    for (int i = 0; i <= 20; ++i) path.emplace_back(0.1 * i, 0.0, 0.0);
    for (int i = 1; i <= 5; ++i) path.emplace_back(2.0 + 0.1 * i, 0.0, 0.06 * i);
    for (int i = 1; i <= 20; ++i) path.emplace_back(2.5 + 0.1 * i, 0.0, 0.3);
    EXPECT_TRUE(drive(path).empty());
}

TEST(TransitRecorder, LongClimbIsThinnedButKeepsItsEnds) {
    TransitRecorder recorder(0.4, 0.0, 16);
    recorder.update({0, 0, 0}, true, 0.0);
    for (int i = 1; i <= 100; ++i) recorder.update({0.1 * i, 0, 0.06 * i}, false, 0.1 * i);
    const std::optional<FloorTransit> t = recorder.update({10.5, 0, 6.0}, true, 11.0);
    ASSERT_TRUE(t.has_value());
    EXPECT_LE(t->floor_path.size(), 17u);
    EXPECT_GE(t->floor_path.size(), 8u);
    EXPECT_EQ(t->floor_path.front(), Eigen::Vector3d(0, 0, 0));
    EXPECT_EQ(t->floor_path.back(), Eigen::Vector3d(10.5, 0, 6.0));
    EXPECT_DOUBLE_EQ(t->stamp_s, 11.0);
}

TEST(TransitRecorder, RejectsBadParameters) {
    EXPECT_THROW(TransitRecorder(0.0), std::invalid_argument);
    EXPECT_THROW(TransitRecorder(0.4, -1.0), std::invalid_argument);
    EXPECT_THROW(TransitRecorder(0.4, 0.1, 2), std::invalid_argument);
}

}  // namespace
}  // namespace stairmap::pipeline
