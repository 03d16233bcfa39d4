// Straight flights read from their profile (DetectorParams::profile_flights, ProfileChains.h):
// scenes of the randomised benchmark's development sets that the detector missed, where far
// level or pitched LiDARs give pieces of the nosings at their own places along each, or every
// other nosing, that no chain of Algorithm 1 joins. Each is found once, on the true nosings, with
// its rise and run, and none of them without the pass; a ramp crossed off its fall line and
// bleachers read at half their tiers' rise by the same search are not reported. Truth from the
// scene description.

#include <gtest/gtest.h>

#include "core/StairDetector.h"
#include "support/BenchmarkScenes.h"
#include "support/SceneExpectations.h"

namespace stairmap {
namespace {

class ReadFromTheProfile : public testing::TestWithParam<test::NamedScene> {};

TEST_P(ReadFromTheProfile, IsFoundOnceWithItsRiseAndRun) {
    const auto found = test::onlyFlightReadOnTruth(GetParam());
    ASSERT_TRUE(found.has_value());
    EXPECT_GE(static_cast<int>(found->first.steps.size()), 7);  // the whole visible flight
}

// Open-riser flights: a level HDL-32 5.9 m from a 16-step flight of 0.113 m rises, lines on 10
// nosings, no two consecutive pieces overlapping (dev3 r0247); a level VLP-16 6 m from 0.115 m
// rises, every other nosing seen higher up (dev2 r0287); far level LiDARs' pieces of ten nosings
// of 0.18 and 0.19 m rises, each at its own place (dev5 r0701, dev6 r0858).
INSTANTIATE_TEST_SUITE_P(
    DevelopmentScenes, ReadFromTheProfile,
    testing::Values(test::NamedScene{4004, 247, "level HDL-32, open risers, pieces, every other"},
                    test::NamedScene{3003, 287, "level VLP-16, open risers, every other nosing"},
                    test::NamedScene{26026, 701, "far level LiDAR, open risers, pieces"},
                    test::NamedScene{28028, 858, "far LiDAR, open risers, pieces"}));

TEST(ReadFromTheProfile, IsWhatTheProfilePassFinds) {
    DetectorParams off;
    off.profile_flights = false;
    test::expectNoneFoundWith({{4004, 247}, {3003, 287}, {26026, 701}, {28028, 858}}, off);
}

TEST(ReadFromTheProfile, RampRingsAndBleachersAreNoFlight) {
    // A pitched HDL-32 6.8 m from a 15 deg ramp whose rings cross it 47 deg off its fall line
    // (dev5 r1079: six evenly spaced level pieces, the surface rising along them), and an
    // elevation map of bleachers 0.39 m high whose tiers make every other tooth of a comb of
    // 0.197 m rises (dev5 r0307: the tiers' treads are level across the put-back "steps").
    for (const int index : {1079, 307}) {
        const sim::RandomCloud scene = test::benchmarkScene(26026, index);
        ASSERT_TRUE(scene.truth.staircases.empty());
        EXPECT_TRUE(
            StairDetector().detect(scene.cloud, scene.truth.observer_floor_z).staircases.empty())
            << "scene " << index;
    }
}

}  // namespace
}  // namespace stairmap
