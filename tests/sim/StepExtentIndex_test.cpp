// measureStepExtents offers each point only to the treads whose windows may hold it (indexed along
// the flight); the result must be exactly that of offering every point to every tread. Flights of
// the randomised benchmark: straight ones whose found nosings turn by a few degrees, spirals.

#include <gtest/gtest.h>

#include <tuple>

#include "core/StairDetector.h"
#include "core/StepExtent.h"
#include "support/BenchmarkScenes.h"

namespace stairmap {
namespace {

class StepExtentIndex : public testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(StepExtentIndex, GivesExactlyTheReferenceExtents) {
    const auto [seed, index] = GetParam();
    const sim::RandomCloud scene = test::benchmarkScene(seed, index);
    const DetectionResult r = StairDetector().detect(scene.cloud, scene.truth.observer_floor_z);
    ASSERT_FALSE(r.staircases.empty());
    StepExtentParams reference;
    reference.index_along_flight = false;
    for (const Staircase& found : r.staircases) {
        Staircase indexed = found, every = found;
        measureStepExtents(scene.cloud, indexed);
        measureStepExtents(scene.cloud, every, reference);
        EXPECT_EQ(indexed.left_side, every.left_side);
        EXPECT_EQ(indexed.right_side, every.right_side);
        EXPECT_EQ(indexed.step_width, every.step_width);
        ASSERT_EQ(indexed.steps.size(), every.steps.size());
        for (std::size_t k = 0; k < every.steps.size(); ++k) {
            EXPECT_EQ(indexed.steps[k].start, every.steps[k].start) << "step " << k;
            EXPECT_EQ(indexed.steps[k].end, every.steps[k].end) << "step " << k;
        }
    }
}

// Dev scenes: debris, ascending and descending flights, and three spirals whose extents differ
// when the index ignores how far the treads' normals turn from the flight's mean (6, 21, 35).
INSTANTIATE_TEST_SUITE_P(DevScenes, StepExtentIndex,
                         testing::Values(std::make_tuple(1001, 5), std::make_tuple(1001, 6),
                                         std::make_tuple(1001, 12), std::make_tuple(1001, 21),
                                         std::make_tuple(1001, 24), std::make_tuple(1001, 35)));

}  // namespace
}  // namespace stairmap
