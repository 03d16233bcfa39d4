// The segmentations shared between the detector's passes: a request gives exactly segmentRows's
// lines for its min_line_points, whichever fewer points the rows were segmented for.
#include "core/RowLinesCache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace stairmap {
namespace {

/// Front-drop cells in dashes of 2-9 columns (2.5 cm apart, 1 cm of noise) at random places and
/// heights 1.5-6 m around the robot, some bent in the middle: rows with lines of every length.
std::vector<TopViewCell> dashedCells(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    std::normal_distribution<float> noise(0.0f, 0.01f);
    std::vector<TopViewCell> cells;
    for (int d = 0; d < 400; ++d) {
        const float r = 1.5f + 4.5f * uni(rng), a = 6.2832f * uni(rng), z = -0.4f + 1.2f * uni(rng);
        const float heading = 6.2832f * uni(rng), bend = uni(rng) < 0.3f ? 0.6f : 0.0f;
        const int n = 2 + static_cast<int>(8 * uni(rng));
        float x = r * std::cos(a), y = r * std::sin(a);
        for (int k = 0; k < n; ++k) {
            const float h = heading + (k > n / 2 ? bend : 0.0f);
            x += 0.025f * std::cos(h);
            y += 0.025f * std::sin(h);
            cells.push_back({x + noise(rng), y + noise(rng), z, kFrontDrop});
        }
    }
    return cells;
}

void expectSameLines(const std::vector<LineSegment>& a, const std::vector<LineSegment>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].num_points, b[i].num_points) << "line " << i;
        EXPECT_EQ(a[i].z, b[i].z) << "line " << i;
        EXPECT_EQ(a[i].start, b[i].start) << "line " << i;
        EXPECT_EQ(a[i].end, b[i].end) << "line " << i;
        EXPECT_EQ(a[i].cov, b[i].cov) << "line " << i;
    }
}

SegmentationParams withPoints(int n) {
    SegmentationParams p;
    p.min_line_length_m = 0.05;  // let the short dashes through: the point count decides
    p.min_line_points = n;
    return p;
}

TEST(RowLinesCache, GivesSegmentRowsLinesForEachPointCount) {
    for (unsigned seed : {1u, 2u, 3u}) {
        const std::vector<TopViewCell> cells = dashedCells(seed);
        CylindricalRows rows;
        buildCylindricalRows(cells, kFrontDrop, CylindricalParams{}, rows);
        RowLinesCache cache;
        std::vector<LineSegment> five, five_direct, four, four_direct;
        // The first pass asks for five points, the rows segmented for four; the second pass's
        // request for four then takes the same segmentation.
        cache.lines(rows, withPoints(5), 4, five);
        cache.lines(rows, withPoints(4), 4, four);
        segmentRows(rows, withPoints(5), five_direct);
        segmentRows(rows, withPoints(4), four_direct);
        ASSERT_LT(five_direct.size(), four_direct.size()) << "the cells make four-point lines";
        expectSameLines(five, five_direct);
        expectSameLines(four, four_direct);
    }
}

TEST(RowLinesCache, SegmentsAgainForFewerPointsThanAskedFirst) {
    const std::vector<TopViewCell> cells = dashedCells(4);
    CylindricalRows rows;
    buildCylindricalRows(cells, kFrontDrop, CylindricalParams{}, rows);
    RowLinesCache cache;
    std::vector<LineSegment> five, three, three_direct;
    cache.lines(rows, withPoints(5), 5, five);  // segmented for five points only
    cache.lines(rows, withPoints(3), 3, three);
    segmentRows(rows, withPoints(3), three_direct);
    expectSameLines(three, three_direct);
}

TEST(RowLinesCache, SegmentsTheNewRowsOnceCleared) {
    CylindricalRows rows;
    buildCylindricalRows(dashedCells(5), kFrontDrop, CylindricalParams{}, rows);
    RowLinesCache cache;
    std::vector<LineSegment> before, after, after_direct;
    cache.lines(rows, withPoints(5), 4, before);
    cache.clear();
    buildCylindricalRows(dashedCells(6), kFrontDrop, CylindricalParams{}, rows);  // same object
    cache.lines(rows, withPoints(5), 4, after);
    segmentRows(rows, withPoints(5), after_direct);
    expectSameLines(after, after_direct);
}

}  // namespace
}  // namespace stairmap
