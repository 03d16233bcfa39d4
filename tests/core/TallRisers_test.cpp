// A nosing put back between two seen ones is refused over a tall riser (bleachers' tiers read as
// two steps each), kept on a flight whose unseen step has its own riser. Clouds are built from
// the known geometry of each case; the expected outcome follows from that geometry.
#include "core/TallRisers.h"

#include <gtest/gtest.h>

#include <vector>

namespace stairmap {
namespace {

constexpr double kRise = 0.22, kRun = 0.33, kWidth = 1.4, kX0 = 3.0, kFloorZ = -0.6;

double xOf(int k) { return kX0 + k * kRun; }  // nosing k of the half-tier reading
double zOf(int k) { return kFloorZ + k * kRise; }

/// Points on the vertical face x = `x` between heights z_lo and z_hi, 1 cm across, 3 cm up.
void addFace(PointCloud& cloud, double x, double z_lo, double z_hi) {
    for (double y = -kWidth / 2; y <= kWidth / 2; y += 0.01)
        for (double z = z_lo + 0.015; z < z_hi; z += 0.03)
            cloud.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

/// Points on the horizontal surface z between x_lo and x_hi, 1 cm across, 3 cm deep.
void addTread(PointCloud& cloud, double z, double x_lo, double x_hi) {
    for (double y = -kWidth / 2; y <= kWidth / 2; y += 0.01)
        for (double x = x_lo + 0.015; x < x_hi; x += 0.03)
            cloud.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

/// A flight of real steps 1..4 (risers at their nosings, treads behind).
PointCloud realSteps() {
    PointCloud cloud;
    for (int k = 1; k <= 4; ++k) {
        addFace(cloud, xOf(k), zOf(k - 1), zOf(k));
        addTread(cloud, zOf(k), xOf(k), xOf(k + 1));
    }
    return cloud;
}

/// Bleachers: tiers two rises tall and two runs deep, their faces at nosings 2 and 4, with the
/// first tier's face seen from nosing 1's height up (a ring line there reads as nosing 1).
PointCloud bleachers(double face_step_m = 0.03) {
    PointCloud cloud;
    addTread(cloud, zOf(0), xOf(0), xOf(2));
    for (int tier = 1; tier <= 2; ++tier) {
        const int k = 2 * tier;
        for (double y = -kWidth / 2; y <= kWidth / 2; y += 0.01)
            for (double z = zOf(k - 2) + 0.015; z < zOf(k); z += face_step_m)
                cloud.emplace_back(static_cast<float>(xOf(k)), static_cast<float>(y),
                                   static_cast<float>(z));
        addTread(cloud, zOf(k), xOf(k), xOf(k + 2));
    }
    return cloud;
}

/// The ascending reading of nosings 1..4 with nosing `unseen` put back (0: all seen).
Staircase reading(int unseen) {
    Staircase s;
    s.direction = StairDirection::Ascending;
    for (int k = 1; k <= 4; ++k) {
        StairEdge e;
        e.start = {xOf(k), kWidth / 2, zOf(k)};
        e.end = {xOf(k), -kWidth / 2, zOf(k)};
        e.num_points = k == unseen ? 0 : 40;
        s.steps.push_back(e);
    }
    return s;
}

TEST(TallRisers, ANosingPutBackOverABleachersTierIsRefused) {
    // Nosing 3 put back between 2 and 4: tier 2's face stands under nosing 4 down to nosing 2.
    EXPECT_TRUE(putBackOverTallRiser(bleachers(), reading(3)));
    std::vector<Staircase> flights = {reading(3)};
    EXPECT_EQ(dropFlightsOverTallRisers(bleachers(), flights), 1);
    EXPECT_TRUE(flights.empty());
}

TEST(TallRisers, AnUnseenStepWithItsOwnRiserIsKept) {
    // The same reading on real steps: riser 4 ends at nosing 3's height, riser 3 stands a run in
    // front of nosing 4.
    EXPECT_FALSE(putBackOverTallRiser(realSteps(), reading(3)));
    std::vector<Staircase> flights = {reading(3)};
    EXPECT_EQ(dropFlightsOverTallRisers(realSteps(), flights), 0);
    EXPECT_EQ(flights.size(), 1u);
}

TEST(TallRisers, OnlyPutBackNosingsAreTested) {
    EXPECT_FALSE(putBackOverTallRiser(bleachers(), reading(0)));  // every nosing seen
    Staircase descending = reading(3);
    descending.direction = StairDirection::Descending;
    EXPECT_FALSE(putBackOverTallRiser(bleachers(), descending));
}

TEST(TallRisers, AFewPointsOnTheStripAreNoTallRiser) {
    TallRiserParams p;
    // One ring across tier 2's face under nosing 4, a point every 10 cm: 13 points, all inside
    // the strip's band (z between nosing 2 + 3 cm and nosing 3 - 6 cm) and its ends.
    PointCloud sparse;
    for (double y = -0.6; y <= 0.6 + 1e-9; y += 0.10)
        sparse.emplace_back(static_cast<float>(xOf(4)), static_cast<float>(y),
                            static_cast<float>(zOf(2) + 0.1));
    ASSERT_LT(static_cast<int>(sparse.size()), p.min_points);
    EXPECT_FALSE(putBackOverTallRiser(sparse, reading(3), p));
    p.min_points = static_cast<int>(sparse.size());
    EXPECT_TRUE(putBackOverTallRiser(sparse, reading(3), p));
}

}  // namespace
}  // namespace stairmap
