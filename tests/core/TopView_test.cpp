// Top view (paper Sec. III-A): highest point per column and nosing candidates, on exact geometry.
#include "core/TopView.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <thread>
#include <utility>

namespace stairmap {
namespace {

constexpr float kFloorZ = -0.5f, kTreadZ = -0.33f;  // one 17 cm step up
constexpr float kStepX = 2.0f, kEndX = 3.0f;        // the tread spans x in [2, 3], |y| < 0.6

/// Floor from x = 0.3 to the step, the tread beyond it, sampled every 1 cm (at least 1.3 mm from
/// any column boundary, so no point's column depends on float rounding) with a distinct tiny
/// height offset per point so that the highest point of every column is unique.
PointCloud stepCloud() {
    PointCloud cloud;
    int k = 0;
    for (int i = 0; 0.3013f + 0.01f * i < kEndX; ++i) {
        for (int j = 0; j < 120; ++j) {
            const float x = 0.3013f + 0.01f * i, y = -0.5987f + 0.01f * j;
            const float z = (x < kStepX ? kFloorZ : kTreadZ) + 1e-6f * static_cast<float>(k++ % 97);
            cloud.emplace_back(x, y, z);
        }
    }
    return cloud;
}

TopViewParams stepParams() {
    TopViewParams p;  // defaults: 2.5 cm columns, 5 cm drop
    p.ground_z_lo = kFloorZ - 0.03;
    p.ground_z_hi = kFloorZ + 0.03;
    return p;
}

TEST(TopView, FrontDropsMarkTheNosingAndNothingInsideTheTread) {
    std::vector<TopViewCell> cells;
    buildTopView(stepCloud(), stepParams(), cells);
    int nosing = 0;
    for (const auto& c : cells) {
        if (!(c.flags & kFrontDrop)) continue;
        // The only ascending nosing candidates are on the tread's near edge (its first column,
        // whose neighbour towards the robot is the lower floor) and not at the sides of the tread,
        // whose radial neighbours are on the tread too.
        EXPECT_NEAR(c.z, kTreadZ, 0.001) << c.x << ", " << c.y;
        EXPECT_LT(c.x, kStepX + 0.05f) << c.x << ", " << c.y;
        ++nosing;
    }
    // The edge is 1.2 m long: about 48 columns of 2.5 cm.
    EXPECT_GE(nosing, 40);
    EXPECT_LE(nosing, 56);
}

/// The step of stepCloud(), but the tread sampled as a far depth camera sees it: rows of points
/// across the ray 12.5 cm apart (pixel rows at a grazing angle), 4 empty columns between them.
PointCloud rowSampledStepCloud() {
    PointCloud cloud;
    int k = 0;
    for (const auto& p : stepCloud()) {
        if (p.x() < kStepX) cloud.push_back(p);  // the floor stays densely sampled
    }
    for (int row = 0; kStepX + 0.0113f + 0.125f * row < kEndX; ++row) {
        for (int j = 0; j < 120; ++j) {
            const float x = kStepX + 0.0113f + 0.125f * row, y = -0.5987f + 0.01f * j;
            cloud.emplace_back(x, y, kTreadZ + 1e-6f * static_cast<float>(k++ % 97));
        }
    }
    return cloud;
}

/// A round platform step around the robot: floor out to kRingR, a 17 cm step up beyond it to
/// kRingEnd, sampled on a 1 cm grid (off the column boundaries).
constexpr float kRingR = 1.5f, kRingEnd = 2.2f;
PointCloud ringStepCloud() {
    PointCloud cloud;
    int k = 0;
    for (int i = 0; i < 440; ++i) {
        for (int j = 0; j < 440; ++j) {
            const float x = -2.1987f + 0.01f * i, y = -2.1987f + 0.01f * j;
            const float r = std::hypot(x, y);
            if (r < 0.3f || r > kRingEnd) continue;
            const float z = (r < kRingR ? kFloorZ : kTreadZ) + 1e-6f * static_cast<float>(k++ % 97);
            cloud.emplace_back(x, y, z);
        }
    }
    return cloud;
}

TEST(TopView, TheNosingIsFoundInEveryDirectionAroundTheRobot) {
    // The radial neighbours are looked up along each column's own direction from the robot: in
    // all eight octants (negative offsets, steep and shallow directions) the step's inner edge is
    // an ascending nosing and the platform's inside is not.
    std::vector<TopViewCell> cells;
    buildTopView(ringStepCloud(), stepParams(), cells);
    int per_octant[8] = {};
    for (const auto& c : cells) {
        const float r = std::hypot(c.x, c.y);
        if (!(c.flags & kFrontDrop)) continue;
        EXPECT_NEAR(c.z, kTreadZ, 0.001) << c.x << ", " << c.y;
        EXPECT_LT(r, kRingR + 0.05f) << c.x << ", " << c.y;  // no candidate inside the platform
        const double octant = std::floor((std::atan2(c.y, c.x) + M_PI) / (M_PI / 4));
        ++per_octant[std::clamp(static_cast<int>(octant), 0, 7)];
    }
    // Each octant's arc of the 1.5 m circle is 1.18 m: about 47 columns of 2.5 cm.
    for (int o = 0; o < 8; ++o) {
        EXPECT_GE(per_octant[o], 40) << "octant " << o;
        EXPECT_LE(per_octant[o], 75) << "octant " << o;
    }
}

TEST(TopView, GapsBetweenRowsOfATreadAreNoDrops) {
    std::vector<TopViewCell> cells;
    buildTopView(rowSampledStepCloud(), stepParams(), cells);
    int nosing = 0, inside = 0;
    for (const auto& c : cells) {
        if (!(c.flags & kFrontDrop) || std::abs(c.y) > 0.5f) continue;
        // The rows behind the first one continue the tread at its height 12.5 cm further on: no
        // surface drops towards the robot there, only at the real step.
        if (c.x < kStepX + 0.05f) {
            ++nosing;
        } else {
            ++inside;
        }
    }
    EXPECT_EQ(inside, 0);
    EXPECT_GE(nosing, 30);  // 1 m of edge (|y| < 0.5): 40 columns
}

TEST(TopView, BackDropsMarkTheFarEndsAndTheFloorIsNoAscendingNosing) {
    std::vector<TopViewCell> cells;
    buildTopView(stepCloud(), stepParams(), cells);
    int far_end = 0;
    for (const auto& c : cells) {
        if (std::abs(c.z - kFloorZ) < 0.01f) {
            EXPECT_FALSE(c.flags & kFrontDrop) << "floor column at " << c.x << ", " << c.y;
        }
        if ((c.flags & kBackDrop) && c.x > kEndX - 0.05f && std::abs(c.y) < 0.5f) ++far_end;
    }
    EXPECT_GE(far_end, 30);  // nothing beyond the tread's end: a drop away from the robot
}

TEST(TopView, ACoarseGridIsOneSurfaceNotADropAtEveryHole) {
    // An elevation map (legged robots' terrain mapping): one point per 4 cm cell, coarser than the
    // 2.5 cm columns, so up to three columns in a row along a ray can be empty. A platform 20 cm up
    // over x in [2, 4], |y| < 1, seen from the origin: only its near edge (front drop) and its far
    // edge and sides (back drop: nothing beyond) are candidates, never a column inside it.
    PointCloud cloud;
    for (float x = 1.02f; x < 4.0f; x += 0.04f)
        for (float y = -0.98f; y < 1.0f; y += 0.04f)
            cloud.emplace_back(x, y, x < 2.0f ? kFloorZ : kFloorZ + 0.20f);
    auto count = [&](double walk_m, int& inside, int& near_edge) {
        TopViewParams p = stepParams();
        p.neighbour_walk_m = walk_m;
        std::vector<TopViewCell> cells;
        buildTopView(cloud, p, cells);
        inside = near_edge = 0;
        for (const auto& c : cells) {
            if (c.z < kFloorZ + 0.1f) continue;  // the floor's own back drops (its far end) aside
            if (c.x > 2.3f && c.x < 3.7f && std::abs(c.y) < 0.7f) ++inside;
            if ((c.flags & kFrontDrop) && c.x < 2.05f) ++near_edge;
        }
    };
    int inside = 0, near_edge = 0;
    count(0.20, inside, near_edge);  // the default walk
    EXPECT_EQ(inside, 0);
    EXPECT_GE(near_edge, 40);  // the 2 m near edge: about 50 cells of 4 cm
    count(0.075, inside, near_edge);  // three columns: holes are taken for drops
    EXPECT_GT(inside, 5);
    EXPECT_GE(near_edge, 40);
}

TEST(TopView, EachCandidateIsTheHighestPointOfItsColumn) {
    const PointCloud cloud = stepCloud();
    const TopViewParams p = stepParams();
    std::vector<TopViewCell> cells;
    buildTopView(cloud, p, cells);
    ASSERT_FALSE(cells.empty());
    for (const auto& c : cells) {
        const int cx = static_cast<int>(std::floor(c.x / p.leaf_m));
        const int cy = static_cast<int>(std::floor(c.y / p.leaf_m));
        const Eigen::Vector3f* best = nullptr;
        for (const auto& q : cloud) {
            if (static_cast<int>(std::floor(q.x() / p.leaf_m)) != cx ||
                static_cast<int>(std::floor(q.y() / p.leaf_m)) != cy)
                continue;
            if (!best || q.z() > best->z()) best = &q;
        }
        ASSERT_NE(best, nullptr) << "a candidate in an empty column at " << c.x << ", " << c.y;
        // The very point (positions stored in 1/65536 of a column).
        EXPECT_NEAR(c.z, best->z(), 1e-6);
        EXPECT_NEAR(c.x, best->x(), 1e-5);
        EXPECT_NEAR(c.y, best->y(), 1e-5);
    }
}

/// Same candidates with the same flags; positions to 0.01 mm (a grid with another origin rounds
/// the in-column positions differently).
testing::AssertionResult sameCells(const std::vector<TopViewCell>& a,
                                   const std::vector<TopViewCell>& b) {
    if (a.size() != b.size())
        return testing::AssertionFailure() << a.size() << " vs " << b.size() << " candidates";
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::abs(a[i].x - b[i].x) > 1e-5f || std::abs(a[i].y - b[i].y) > 1e-5f ||
            std::abs(a[i].z - b[i].z) > 1e-5f || a[i].flags != b[i].flags)
            return testing::AssertionFailure()
                   << "candidate " << i << ": (" << a[i].x << ", " << a[i].y << ", " << a[i].z
                   << ") flags " << int(a[i].flags) << " vs (" << b[i].x << ", " << b[i].y << ", "
                   << b[i].z << ") flags " << int(b[i].flags);
    }
    return testing::AssertionSuccess();
}

TEST(TopView, PointOrderDoesNotMatter) {
    PointCloud cloud = stepCloud();
    std::vector<TopViewCell> ordered, shuffled;
    buildTopView(cloud, stepParams(), ordered);
    std::mt19937 rng(5);
    std::shuffle(cloud.begin(), cloud.end(), rng);
    buildTopView(cloud, stepParams(), shuffled);
    EXPECT_TRUE(sameCells(ordered, shuffled));
}

TEST(TopView, NonFinitePointsAndPointsOutOfRangeOrBandAreIgnored) {
    const PointCloud clean = stepCloud();
    PointCloud dirty = clean;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    dirty.emplace_back(nan, 0.f, 0.f);
    dirty.emplace_back(2.5f, nan, -0.3f);
    dirty.emplace_back(2.5f, 0.1f, nan);
    dirty.emplace_back(inf, 0.f, -0.3f);
    dirty.emplace_back(-inf, -inf, -inf);
    dirty.emplace_back(2.5f, 0.2f, 3.5f);   // above z_hi (3 m): a ceiling
    dirty.emplace_back(2.5f, 0.2f, -3.5f);  // below z_lo
    dirty.emplace_back(40.f, 0.f, -0.3f);   // beyond max_range (10 m)
    dirty.emplace_back(7.2f, 7.2f, -0.3f);  // inside the +-10 m box, beyond the 10 m circle
    std::vector<TopViewCell> a, b;
    buildTopView(clean, stepParams(), a);
    buildTopView(dirty, stepParams(), b);
    EXPECT_TRUE(sameCells(a, b));
}

// The grid is scratch memory kept per thread between calls, and each call clears only what it
// wrote: a wide, dense cloud gridded first (its columns cover the whole scratch grid, at other
// offsets than the step's) must leave nothing behind for the next cloud, which must read as in a
// thread that never gridded anything.
TEST(TopView, NothingOfAnEarlierCloudRemainsInTheNext) {
    const PointCloud step = stepCloud();
    std::vector<TopViewCell> fresh;
    std::thread([&] { buildTopView(step, stepParams(), fresh); }).join();
    ASSERT_FALSE(fresh.empty());

    PointCloud wide;
    for (int i = 0; i < 640; ++i)
        for (int j = 0; j < 640; ++j) {
            const float x = -8.f + 0.025f * i + 0.0123f, y = -8.f + 0.025f * j + 0.0117f;
            wide.emplace_back(x, y, (i / 40 + j / 40) % 2 ? 0.4f : -0.2f);  // 1 m checkerboard
        }
    std::vector<TopViewCell> before, after;
    buildTopView(wide, stepParams(), before);
    ASSERT_FALSE(before.empty());
    buildTopView(step, stepParams(), after);
    EXPECT_TRUE(sameCells(fresh, after));
}

TEST(TopView, EmptyAndAllInvalidCloudsGiveNoCells) {
    std::vector<TopViewCell> cells{{1, 2, 3, kFrontDrop}};
    buildTopView({}, stepParams(), cells);
    EXPECT_TRUE(cells.empty());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    buildTopView({{nan, nan, nan}, {50.f, 50.f, 0.f}}, stepParams(), cells);
    EXPECT_TRUE(cells.empty());
}

// --- The rules read directly (TopView.h), column by column, against the fast implementation ---

/// A terrain of random blocks around the robot (behind and beside it too) at levels chosen well
/// away from every threshold: the floor and a 4 cm rise (spill: between edge_spill_dz_m and
/// edge_min_dz_m, inside the ground band), 17 and 34 cm steps, an 80 cm wall (above
/// edge_spill_max_dz_m). Densely sampled blocks, sparse ones (holes along the walks) and empty
/// ones; every point 2.5 mm or more from its column's borders, so that the column of a point does
/// not depend on float rounding.
PointCloud blockTerrain(unsigned seed, double leaf) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double levels[] = {0.0, 0.04, 0.17, 0.34, 0.80};
    constexpr int kBlocks = 12;  // 12 x 12 blocks of 0.5 m over [-3, 3] m
    PointCloud cloud;
    for (int bx = 0; bx < kBlocks; ++bx) {
        for (int by = 0; by < kBlocks; ++by) {
            const double level = levels[rng() % 5];
            const double density = std::array<double, 4>{0.0, 0.08, 0.4, 1.6}[rng() % 4];
            const int per_block = static_cast<int>(density * 400);  // 400 columns per block
            for (int k = 0; k < per_block; ++k) {
                const int ix =
                    static_cast<int>((-3.0 + 0.5 * bx) / leaf) + static_cast<int>(rng() % 20);
                const int iy =
                    static_cast<int>((-3.0 + 0.5 * by) / leaf) + static_cast<int>(rng() % 20);
                const double x = (ix + 0.1 + 0.8 * unit(rng)) * leaf;
                const double y = (iy + 0.1 + 0.8 * unit(rng)) * leaf;
                const double z = level + 0.003 * (2 * unit(rng) - 1);
                cloud.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(z));
            }
        }
    }
    cloud.emplace_back(std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f);
    cloud.emplace_back(12.f, 0.f, 0.f);                              // beyond max_range
    if (cloud.size() % 4 == 0) cloud.emplace_back(0.5f, 0.5f, 4.f);  // above z_hi; a ragged tail
    return cloud;
}

/// TopView.h's rules, column by column, in double precision and the plainest loops.
/// A candidate column: its flags and its highest point's height [m].
struct RuleCell {
    std::uint8_t flags;
    double z;
};

std::map<std::pair<int, int>, RuleCell> candidatesByTheRules(const PointCloud& cloud,
                                                             const TopViewParams& p) {
    std::map<std::pair<int, int>, double> top;  // highest point per column
    for (const auto& q : cloud) {
        if (!q.allFinite() || q.z() < p.z_lo || q.z() > p.z_hi ||
            std::hypot(q.x(), q.y()) > p.max_range_m)
            continue;
        const std::pair<int, int> c{static_cast<int>(std::floor(q.x() / p.leaf_m)),
                                    static_cast<int>(std::floor(q.y() / p.leaf_m))};
        auto it = top.find(c);
        if (it == top.end() || q.z() > it->second) top[c] = q.z();
    }
    const int walk = static_cast<int>(std::lround(p.neighbour_walk_m / p.leaf_m));
    std::map<std::pair<int, int>, RuleCell> out;
    for (const auto& [c, z] : top) {
        const double cx = (c.first + 0.5) * p.leaf_m, cy = (c.second + 0.5) * p.leaf_m;
        const double ux = cx / std::hypot(cx, cy), uy = cy / std::hypot(cx, cy);
        struct Side {
            bool drop = false;
            std::optional<double> first;
        };
        auto look = [&](int sign) {  // walk away from (+1) or towards (-1) the robot
            Side s;
            for (int k = 1; k <= walk; ++k) {
                const std::pair<int, int> n{
                    c.first + sign * static_cast<int>(std::floor(k * ux + 0.5)),
                    c.second + sign * static_cast<int>(std::floor(k * uy + 0.5))};
                const auto it = top.find(n);
                if (it == top.end()) continue;  // a hole is looked past
                if (!s.first) s.first = it->second;
                if (it->second < z - p.edge_min_dz_m) {
                    s.drop = true;
                    return s;
                }
                if (it->second < z + p.edge_spill_max_dz_m) return s;  // about the same level
            }                                                          // (a wall is looked past)
            s.drop = !s.first;                                         // nothing within the walk
            return s;
        };
        const bool ground = z > p.ground_z_lo && z < p.ground_z_hi;
        const Side front = ground ? Side{} : look(-1), back = look(+1);
        auto spill = [&](const Side& s) {
            return s.first && *s.first > z + p.edge_spill_dz_m &&
                   *s.first < z + p.edge_spill_max_dz_m;
        };
        const std::uint8_t flags = (front.drop && !spill(back) ? kFrontDrop : 0) |
                                   (back.drop && !spill(front) ? kBackDrop : 0);
        if (flags) out[c] = {flags, z};
    }
    return out;
}

TEST(TopView, FollowsItsRulesColumnByColumnOnRandomTerrain) {
    // The fast implementation (packed column words, SIMD passes, first-step shortcut, flat
    // neighbourhoods, segment marks) against the rules read plainly: the same candidate columns,
    // flags and heights, for two walk lengths and a ground band.
    int compared = 0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        for (double walk_m : {0.20, 0.10}) {
            TopViewParams p;
            p.neighbour_walk_m = walk_m;
            p.edge_spill_max_dz_m = 0.11;
            p.ground_z_lo = -0.05;
            p.ground_z_hi = 0.05;
            const PointCloud cloud = blockTerrain(seed, p.leaf_m);
            const auto expected = candidatesByTheRules(cloud, p);
            std::vector<TopViewCell> cells;
            buildTopView(cloud, p, cells);
            std::map<std::pair<int, int>, RuleCell> got;
            for (const auto& c : cells)
                got[{static_cast<int>(std::floor(c.x / p.leaf_m)),
                     static_cast<int>(std::floor(c.y / p.leaf_m))}] = {c.flags, c.z};
            ASSERT_GT(expected.size(), 500u) << "seed " << seed;
            EXPECT_EQ(got.size(), cells.size()) << "seed " << seed << ": two cells in one column";
            int wrong = 0;
            for (const auto& [c, cell] : expected) {
                const auto it = got.find(c);
                if (it == got.end() || it->second.flags != cell.flags ||
                    std::abs(it->second.z - cell.z) > 1e-5)
                    ++wrong;
            }
            for (const auto& [c, cell] : got) wrong += expected.count(c) ? 0 : 1;
            EXPECT_EQ(wrong, 0) << "seed " << seed << ", walk " << walk_m
                                << " m: " << expected.size() << " candidates by the rules, "
                                << got.size() << " found";
            compared += static_cast<int>(expected.size());
        }
    }
    EXPECT_GT(compared, 10000);
}

}  // namespace
}  // namespace stairmap
