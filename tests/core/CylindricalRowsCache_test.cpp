// The cylindrical arrays kept between a detector's passes: the same array for the same flag and
// rows, a separate one otherwise, and the new cells' array once cleared.
#include "core/CylindricalRows.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>
#include <vector>

namespace stairmap {
namespace {

/// Two candidate cells 2 m ahead at 0.1 m and 0.3 m height, front drops, and one back drop.
std::vector<TopViewCell> someCells() {
    return {{2.0f, 0.0f, 0.1f, kFrontDrop}, {2.0f, 0.5f, 0.3f, kFrontDrop},
            {3.0f, 0.0f, 0.2f, kBackDrop}};
}

/// Distinct cells in the array (each cell lies in two overlapping rows).
int pointsIn(const CylindricalRows& rows) {
    std::set<std::tuple<float, float, float>> cells;
    for (std::size_t i = 0; i < rows.x.size(); ++i) cells.insert({rows.x[i], rows.y[i], rows.z[i]});
    return static_cast<int>(cells.size());
}

TEST(CylindricalRowsCache, GivesTheSameArrayForTheSameFlagAndRows) {
    const std::vector<TopViewCell> cells = someCells();
    CylindricalRowsCache cache;
    CylindricalParams p;
    const CylindricalRows& first = cache.rows(cells, kFrontDrop, p);
    EXPECT_EQ(pointsIn(first), 2);
    EXPECT_EQ(&cache.rows(cells, kFrontDrop, p), &first);
    const CylindricalRows& back = cache.rows(cells, kBackDrop, p);
    EXPECT_NE(&back, &first);
    EXPECT_EQ(pointsIn(back), 1);
    CylindricalParams taller = p;
    taller.row_height_m = 0.05;
    const CylindricalRows& tall = cache.rows(cells, kFrontDrop, taller);
    EXPECT_NE(&tall, &first);
    EXPECT_EQ(pointsIn(tall), 2);
    EXPECT_EQ(pointsIn(cache.rows(cells, kFrontDrop, p)), 2);  // still the first one
}

TEST(CylindricalRowsCache, BuildsFromTheNewCellsOnceCleared) {
    CylindricalRowsCache cache;
    CylindricalParams p;
    const std::vector<TopViewCell> before = someCells();
    EXPECT_EQ(pointsIn(cache.rows(before, kFrontDrop, p)), 2);
    cache.clear();
    const std::vector<TopViewCell> after = {{1.0f, 1.0f, 0.5f, kFrontDrop}};
    const CylindricalRows& rows = cache.rows(after, kFrontDrop, p);
    ASSERT_EQ(pointsIn(rows), 1);
    EXPECT_FLOAT_EQ(rows.x[0], 1.0f);
    EXPECT_FLOAT_EQ(rows.z[0], 0.5f);
}

}  // namespace
}  // namespace stairmap
