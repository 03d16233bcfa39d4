// Map alignment on synthetic landmark maps with known transforms: recovery, wrong pairings,
// noise, and the refusals (no shared staircase, ambiguous partial flight, identical flights).
#include <gtest/gtest.h>

#include "fleet/MapAlignment.h"
#include "fleet/StaircasePairing.h"
#include "FleetTestMaps.h"

namespace stairmap::fleet::test {
namespace {

/// Two different straight flights and a spiral, each seen partially (no end observed).
std::vector<FlightSpec> building() {
    FlightSpec a;  // straight, 16 risers, seen levels 3..10
    a.foot = {2.0, 0.8};
    a.first_level = 3;
    a.last_level = 10;
    FlightSpec b;  // another flight 12 m away, other heading, steeper
    b.foot = {14.0, 6.0};
    b.heading_deg = 120.0;
    b.rise = 0.17;
    b.run = 0.26;
    b.first_level = 2;
    b.last_level = 7;
    FlightSpec c;  // spiral
    c.foot = {6.0, -5.0};
    c.heading_deg = 30.0;
    c.spiral_turn_deg = 22.0;
    c.rise = 0.19;
    c.run = 0.0;
    c.width = 0.9;
    c.first_level = 1;
    c.last_level = 6;
    return {a, b, c};
}

LandmarkMapState buildingMap(const std::vector<FlightSpec>& specs, std::mt19937* noise = nullptr,
                             double sigma = 0.0) {
    std::vector<StaircaseLandmark> lms;
    for (std::size_t i = 0; i < specs.size(); ++i)
        lms.push_back(makeLandmark(specs[i], static_cast<int>(i), noise, sigma));
    return makeMap(lms);
}

class KnownTransform : public ::testing::TestWithParam<Transform4> {};

TEST_P(KnownTransform, RecoveredFromTwoFlightsAndASpiral) {
    const Transform4 T = GetParam();
    const auto specs = building();
    const LandmarkMapState first = buildingMap(specs);
    const LandmarkMapState other = inOtherFrame(buildingMap(specs), T);
    const AlignmentResult r = estimateAlignment(first, other);
    ASSERT_EQ(r.status, AlignmentStatus::Aligned) << r.reason;
    EXPECT_NEAR(r.T_first_other.x, T.x, 0.005);
    EXPECT_NEAR(r.T_first_other.y, T.y, 0.005);
    EXPECT_NEAR(r.T_first_other.z, T.z, 0.005);
    EXPECT_LT(yawErrorDeg(r.T_first_other.yaw_rad, T.yaw_rad), 0.05);
    ASSERT_EQ(r.pairs.size(), 3u);
    for (const LandmarkPair& p : r.pairs) EXPECT_EQ(p.first_id, p.other_id);
}

TEST_P(KnownTransform, RecoveredWithNoiseAndWrongPairings) {
    const Transform4 T = GetParam();
    std::mt19937 rng(7);
    auto specs = building();
    const LandmarkMapState first = buildingMap(specs, &rng, 0.01);
    // The other robot also saw a decoy: a flight shaped like the first one (same rise, run,
    // width) somewhere the first robot never went, so pairing it is wrong.
    FlightSpec decoy = specs[0];
    decoy.foot = {-8.0, 3.0};
    decoy.heading_deg = 250.0;
    specs.push_back(decoy);
    LandmarkMapState other = inOtherFrame(buildingMap(specs, &rng, 0.01), T);
    const AlignmentResult r = estimateAlignment(first, other);
    ASSERT_EQ(r.status, AlignmentStatus::Aligned) << r.reason;
    EXPECT_NEAR(r.T_first_other.x, T.x, 0.03);
    EXPECT_NEAR(r.T_first_other.y, T.y, 0.03);
    EXPECT_NEAR(r.T_first_other.z, T.z, 0.01);
    EXPECT_LT(yawErrorDeg(r.T_first_other.yaw_rad, T.yaw_rad), 0.5);
    EXPECT_EQ(r.pairs.size(), 3u);
    for (const LandmarkPair& p : r.pairs) EXPECT_NE(p.other_id, 3) << "decoy paired";
    EXPECT_GT(r.sigma.xy_m, 0.0);
    EXPECT_LT(r.sigma.xy_m, 0.05);
    EXPECT_LT(r.sigma.yaw_deg, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Transforms, KnownTransform,
                         ::testing::Values(Transform4{0, 0, 0, 0}, Transform4{3.0, -2.0, 0.5, 0.7},
                                           Transform4{-10.0, 4.0, -3.0, -1.9},
                                           Transform4{1.0, 1.0, 2.0, M_PI},
                                           Transform4{0.4, -7.0, 0.0, 3.13}),
                         [](const ::testing::TestParamInfo<Transform4>& param_info) {
                             return "case" + std::to_string(param_info.index);
                         });

TEST(MapAlignment, OneFlightSeenFromTheSameEndIsEnough) {
    FlightSpec f;
    f.foot = {1.0, 2.0};
    f.heading_deg = 40.0;
    f.first_level = 1;
    f.last_level = 9;
    f.bottom_observed = true;
    FlightSpec g = f;
    g.last_level = 5;  // the other robot saw fewer steps, from the same (bottom) end
    const Transform4 T{2.0, -1.0, 1.5, 2.5};
    const AlignmentResult r = estimateAlignment(makeMap({makeLandmark(f, 0)}),
                                                inOtherFrame(makeMap({makeLandmark(g, 4)}), T));
    ASSERT_EQ(r.status, AlignmentStatus::Aligned) << r.reason;
    EXPECT_NEAR(r.T_first_other.z, T.z, 0.005);
    EXPECT_NEAR(r.T_first_other.x, T.x, 0.01);
    EXPECT_NEAR(r.T_first_other.y, T.y, 0.01);
    ASSERT_EQ(r.pairs.size(), 1u);
    EXPECT_EQ(r.pairs[0].first_id, 0);
    EXPECT_EQ(r.pairs[0].other_id, 4);
}

TEST(MapAlignment, PartialViewsFromOppositeEndsAreAmbiguous) {
    FlightSpec top;  // the first robot looked down from the top ...
    top.first_level = 8;
    top.last_level = 16;
    top.top_observed = true;
    FlightSpec bottom;  // ... the other walked to the foot
    bottom.first_level = 1;
    bottom.last_level = 9;
    bottom.bottom_observed = true;
    const AlignmentResult r = estimateAlignment(
        makeMap({makeLandmark(top, 0)}),
        inOtherFrame(makeMap({makeLandmark(bottom, 0)}), Transform4{1, 2, 0.3, 1.0}));
    EXPECT_EQ(r.status, AlignmentStatus::Ambiguous);
    EXPECT_GE(r.alternatives.size(), 2u);
    EXPECT_FALSE(r.reason.empty());
}

TEST(MapAlignment, OneOfTwoIdenticalFlightsIsAmbiguous) {
    FlightSpec a;
    a.first_level = 1;
    a.last_level = 10;
    a.bottom_observed = true;
    FlightSpec b = a;  // the same flight, 10 m away and turned: a building with twin stairwells
    b.foot = {12.0, 5.0};
    b.heading_deg = 180.0;
    const AlignmentResult r = estimateAlignment(
        makeMap({makeLandmark(a, 0), makeLandmark(b, 1)}),
        inOtherFrame(makeMap({makeLandmark(a, 0)}), Transform4{-1, 0.5, 0, 0.3}));
    EXPECT_EQ(r.status, AlignmentStatus::Ambiguous);
    EXPECT_EQ(r.alternatives.size(), 2u);
}

TEST(MapAlignment, BothIdenticalFlightsSeenByBothFixTheTransform) {
    FlightSpec a;
    a.first_level = 1;
    a.last_level = 10;
    a.bottom_observed = true;
    FlightSpec b = a;
    b.foot = {12.0, 5.0};
    b.heading_deg = 90.0;
    const Transform4 T{-1, 0.5, 0, 0.3};
    const auto map = makeMap({makeLandmark(a, 0), makeLandmark(b, 1)});
    const AlignmentResult r = estimateAlignment(map, inOtherFrame(map, T));
    ASSERT_EQ(r.status, AlignmentStatus::Aligned) << r.reason;
    EXPECT_NEAR(r.T_first_other.x, T.x, 0.005);
    EXPECT_EQ(r.pairs.size(), 2u);
}

TEST(MapAlignment, NoSharedStaircaseIsRefused) {
    FlightSpec a;
    FlightSpec b;
    b.rise = 0.12;  // a different flight: shallower steps
    b.run = 0.35;
    EXPECT_EQ(estimateAlignment(makeMap({makeLandmark(a, 0)}), makeMap({makeLandmark(b, 0)})).status,
              AlignmentStatus::NoSharedStaircase);
    EXPECT_EQ(estimateAlignment(makeMap({makeLandmark(a, 0)}), LandmarkMapState{}).status,
              AlignmentStatus::NoSharedStaircase);
    EXPECT_EQ(estimateAlignment(LandmarkMapState{}, LandmarkMapState{}).status,
              AlignmentStatus::NoSharedStaircase);
}

TEST(MapAlignment, GivenTransformIsKeptAndItsPairsReported) {
    const auto specs = building();
    const Transform4 T{5, 5, 1, -0.4};
    const auto first = buildingMap(specs);
    const AlignmentResult r = evaluateAlignment(first, inOtherFrame(first, T), T);
    EXPECT_EQ(r.status, AlignmentStatus::Aligned);
    EXPECT_DOUBLE_EQ(r.T_first_other.x, T.x);
    EXPECT_EQ(r.pairs.size(), 3u);
}

TEST(StaircasePairing, ShiftsRespectObservedEnds) {
    FlightSpec f;
    f.first_level = 1;
    f.last_level = 6;
    FlightView a, b;
    a.stairs = makeLandmark(f, 0).stairs;
    b.stairs = a.stairs;
    EXPECT_EQ(candidateShifts(a, b, {}).size(), 11u);  // -5..5: any overlap
    a.bottom_observed = b.bottom_observed = true;
    EXPECT_EQ(candidateShifts(a, b, {}), std::vector<int>{0});
}

}  // namespace
}  // namespace stairmap::fleet::test
