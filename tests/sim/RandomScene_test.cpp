// The random benchmark generator: deterministic for a seed, every drawn parameter inside the
// issue-10 ranges with the intended family shares, and gt.json nosings lying on the solids.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "sim/RandomCloud.h"
#include "sim/RandomFlightGeometry.h"
#include "sim/RandomScene.h"
#include "sim/RandomSceneBuild.h"

namespace stairmap::sim {
namespace {

constexpr int kDraws = 600;
const RandomRanges kRanges;

bool sameFlight(const FlightSpec& a, const FlightSpec& b) {
    return a.spiral == b.spiral && a.steps == b.steps && a.rise_m == b.rise_m && a.run_m == b.run_m &&
           a.width_m == b.width_m && a.distance_m == b.distance_m && a.heading_deg == b.heading_deg &&
           a.offset_steps == b.offset_steps && a.left == b.left && a.right == b.right;
}

TEST(RandomScene, SameSeedSameDescriptionOtherSeedOther) {
    int differ = 0;
    for (int i = 0; i < 50; ++i) {
        const auto a = drawRandomScene(11, i), b = drawRandomScene(11, i), c = drawRandomScene(12, i);
        ASSERT_EQ(a.family, b.family);
        ASSERT_EQ(a.flights.size(), b.flights.size());
        for (std::size_t f = 0; f < a.flights.size(); ++f) EXPECT_TRUE(sameFlight(a.flights[f], b.flights[f]));
        EXPECT_EQ(a.sensor.model, b.sensor.model);
        EXPECT_EQ(a.sensor.pitch_deg, b.sensor.pitch_deg);
        EXPECT_EQ(a.noise_seed, b.noise_seed);
        if (a.sensor.base_height_m != c.sensor.base_height_m) ++differ;
    }
    EXPECT_GE(differ, 49);
}

TEST(RandomScene, SameSeedSameCloud) {
    const auto a = makeRandomCloud(5, 3), b = makeRandomCloud(5, 3);
    ASSERT_FALSE(a.cloud.empty());
    ASSERT_EQ(a.cloud.size(), b.cloud.size());
    for (std::size_t i = 0; i < a.cloud.size(); i += 97) EXPECT_EQ(a.cloud[i], b.cloud[i]);
    EXPECT_EQ(a.seen_nosings, b.seen_nosings);
}

void expectFlightInRanges(const FlightSpec& f, const SensorSpec& s) {
    EXPECT_GE(f.rise_m, kRanges.rise_min_m);
    EXPECT_LE(f.rise_m, kRanges.rise_max_m);
    EXPECT_GE(f.run_m, kRanges.run_min_m - 1e-9);
    EXPECT_LE(f.run_m, kRanges.run_max_m + 1e-9);
    EXPECT_GE(f.steps, kRanges.steps_min);
    EXPECT_LE(f.steps, kRanges.steps_max);
    EXPECT_GE(f.distance_m, kRanges.distance_min_m);
    const bool near = s.kind == RandomSensorKind::DepthCamera || s.kind == RandomSensorKind::ElevationMap;
    EXPECT_LE(f.distance_m, near ? kRanges.depth_distance_max_m : kRanges.distance_max_m);
    EXPECT_LE(std::abs(f.offset_steps), kRanges.offset_steps_max);
    EXPECT_TRUE(robotClear(f));
    if (f.spiral) {
        EXPECT_GE(f.width_m, kRanges.spiral_width_min_m);
        EXPECT_LE(f.width_m, kRanges.spiral_width_max_m);
        EXPECT_GE(f.column_radius_m, kRanges.column_min_m);
        EXPECT_LE(f.column_radius_m, kRanges.column_max_m);
        EXPECT_GT(f.step_angle_deg * f.steps, 180.0);  // more than a half turn
        EXPECT_LT(f.step_angle_deg * f.steps, 330.0);
    } else {
        EXPECT_GE(f.width_m, kRanges.width_min_m);
        EXPECT_LE(f.width_m, kRanges.width_max_m);
    }
}

void expectSensorInRanges(const SensorSpec& s) {
    EXPECT_GE(s.scans, kRanges.scans_min);
    EXPECT_LE(s.scans, kRanges.scans_max);
    if (s.kind == RandomSensorKind::PitchedLidar) {
        EXPECT_GE(s.pitch_deg, kRanges.lidar_pitch_min_deg);
        EXPECT_LE(s.pitch_deg, kRanges.lidar_pitch_max_deg);
    } else if (s.kind == RandomSensorKind::DepthCamera) {
        EXPECT_GE(s.pitch_deg, kRanges.camera_pitch_min_deg);
        EXPECT_LE(s.pitch_deg, kRanges.camera_pitch_max_deg);
    } else if (s.kind == RandomSensorKind::ElevationMap) {
        EXPECT_GE(s.cell_m, kRanges.cell_min_m);
        EXPECT_LE(s.cell_m, kRanges.cell_max_m);
    } else {
        EXPECT_EQ(s.pitch_deg, 0.0);
    }
}

void expectNegativeInRanges(const NegativeSpec& n) {
    if (n.type == "ramp_up" || n.type == "ramp_down") {
        EXPECT_GE(n.slope_deg, kRanges.ramp_min_deg);
        EXPECT_LE(n.slope_deg, kRanges.ramp_max_deg);
    } else if (n.type == "stage") {
        EXPECT_GE(n.tiers, 1);
        EXPECT_LE(n.tiers, 2);
    } else if (n.type == "bleachers") {
        EXPECT_GE(n.height_m, kRanges.bleacher_rise_min_m);
        EXPECT_LE(n.height_m, kRanges.bleacher_rise_max_m);
    }
}

TEST(RandomScene, DrawsStayInRangesWithTheIntendedShares) {
    std::map<RandomFamily, int> families;
    std::set<std::string> models, negatives, sides;
    int clockwise = 0, open_spiral = 0, balusters = 0, above = 0, below = 0, two = 0, spirals = 0;
    for (int i = 0; i < kDraws; ++i) {
        const auto spec = drawRandomScene(7, i);
        ++families[spec.family];
        models.insert(spec.sensor.model);
        expectSensorInRanges(spec.sensor);
        EXPECT_EQ(spec.flights.empty(), spec.family == RandomFamily::Negative);
        for (const auto& f : spec.flights) {
            expectFlightInRanges(f, spec.sensor);
            above += f.offset_steps > 0;
            below += f.offset_steps < 0;
            sides.insert(sideKindName(f.left));
            if (f.spiral) {
                ++spirals;
                clockwise += f.clockwise;
                open_spiral += f.open_risers;
                balusters += f.balusters;
            }
        }
        two += spec.flights.size() == 2;
        if (spec.flights.size() == 2) {
            EXPECT_FALSE(footprintsOverlap(spec.flights[0], spec.flights[1], 0.5));
        }
        for (const auto& n : spec.extras) {
            negatives.insert(n.type);
            expectNegativeInRanges(n);
        }
    }
    const std::map<RandomFamily, double> share = {
        {RandomFamily::Ascending, 0.20}, {RandomFamily::Hollow, 0.12}, {RandomFamily::Spiral, 0.14},
        {RandomFamily::Descending, 0.18}, {RandomFamily::Debris, 0.12}, {RandomFamily::Negative, 0.24}};
    for (const auto& [family, p] : share)
        EXPECT_NEAR(families[family] / double(kDraws), p, 0.05) << familyName(family);
    EXPECT_EQ(models, (std::set<std::string>{"vlp16", "hdl32", "os1_64", "os0_128", "depth_camera", "elevation_map"}));
    EXPECT_EQ(negatives.size(), 7u);
    EXPECT_EQ(sides.size(), 3u);
    EXPECT_GT(clockwise, spirals / 4);
    EXPECT_LT(clockwise, 3 * spirals / 4);
    EXPECT_GT(open_spiral, spirals / 4);
    EXPECT_GT(balusters, spirals / 4);
    EXPECT_GT(above, 10);
    EXPECT_GT(below, 10);
    EXPECT_GT(two, 10);
}

/// Height of the first surface below (x, y) from z_from.
double surfaceBelow(const Scene& scene, const Eigen::Vector3d& p) {
    Ray ray;
    ray.origin = p;
    ray.direction = -Eigen::Vector3d::UnitZ();
    const auto t = scene.castRay(ray, 20.0);
    return t ? p.z() - *t : -1e9;
}

TEST(RandomScene, TruthNosingsLieOnTheTreads) {
    int checked = 0;
    for (int i = 0; i < 80; ++i) {
        const auto spec = drawRandomScene(3, i);
        if (spec.flights.empty()) continue;
        const Scene scene = buildRandomScene(spec);
        ASSERT_EQ(scene.truth().staircases.size(), spec.flights.size());
        for (std::size_t s = 0; s < spec.flights.size(); ++s) {
            const auto& stair = scene.truth().staircases[s];
            ASSERT_EQ(static_cast<int>(stair.nosings.size()), spec.flights[s].steps + 1);
            const bool debris = spec.flights[s].debris_count > 0;
            for (std::size_t k = 0; k < stair.nosings.size(); ++k) {
                const auto& n = stair.nosings[k];
                const Eigen::Vector3d along = n.end - n.start;
                Eigen::Vector3d up_flight(-along.y(), along.x(), 0.0);
                up_flight.normalize();
                const auto& other = stair.nosings[k + 1 < stair.nosings.size() ? k + 1 : k - 1];
                if (up_flight.dot(other.centre() - n.centre()) * (k + 1 < stair.nosings.size() ? 1 : -1) < 0)
                    up_flight = -up_flight;
                for (double a : {0.3, 0.5, 0.7}) {
                    const Eigen::Vector3d p = n.start + a * along + Eigen::Vector3d(0, 0, 0.05);
                    const double tread = surfaceBelow(scene, p + 0.03 * up_flight);
                    const double below = surfaceBelow(scene, p - 0.03 * up_flight);
                    if (debris) {
                        EXPECT_GE(tread, n.start.z() - 0.002);
                    } else {
                        EXPECT_NEAR(tread, n.start.z(), 0.002) << "scene " << i << " nosing " << k;
                        EXPECT_NEAR(below, n.start.z() - stair.rise_m, 0.002) << "scene " << i << " nosing " << k;
                    }
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(RandomScene, ExpectedFlightsAreSeenAndTruthIsInTheRobotFrame) {
    for (int i = 0; i < 4; ++i) {
        const auto rc = makeRandomCloud(9, i);
        ASSERT_TRUE(rc.truth.observer_floor_z.has_value());
        EXPECT_NEAR(*rc.truth.observer_floor_z, -rc.spec.sensor.base_height_m, 1e-9);
        ASSERT_EQ(rc.seen_nosings.size(), rc.truth.staircases.size());
        for (std::size_t s = 0; s < rc.truth.staircases.size(); ++s) {
            EXPECT_EQ(rc.truth.staircases[s].seen_as.has_value(), rc.seen_nosings[s] >= kExpectedNosings);
            if (rc.attempts < 6) {
                EXPECT_TRUE(rc.seen_nosings[s] <= 1 || rc.seen_nosings[s] >= kExpectedNosings);
            }
        }
    }
}

}  // namespace
}  // namespace stairmap::sim
