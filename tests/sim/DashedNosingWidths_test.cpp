// Widths of flights whose nosings a far ring hits in dashes (StepExtentParams::max_open_gap_m):
// scenes of the randomised benchmark's development sets where the steps ended at the first hole
// between two dashes and the flight read 0.9-1.2 m narrow. Each is now read within 10 cm of its
// true width. Truth from the scene description.

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>

#include "support/BenchmarkScenes.h"
#include "support/SceneExpectations.h"

namespace stairmap {
namespace {

struct DashedCase {
    int seed = 0, index = 0;
    const char* why = "";
};

std::ostream& operator<<(std::ostream& os, const DashedCase& c) {
    return os << "seed " << c.seed << " scene " << c.index << " (" << c.why << ")";
}

class DashedNosings : public testing::TestWithParam<DashedCase> {};

TEST_P(DashedNosings, TheFlightIsReadAsWideAsItIs) {
    const DashedCase& c = GetParam();
    const sim::RandomCloud scene = test::benchmarkScene(c.seed, c.index);
    ASSERT_EQ(scene.truth.staircases.size(), 1u);
    const StaircaseTruth& truth = scene.truth.staircases.front();
    ASSERT_TRUE(scene.truth.observer_floor_z.has_value());
    const auto on_truth = test::flightsReadOnTruth(scene, truth, *scene.truth.observer_floor_z);
    ASSERT_EQ(on_truth.size(), 1u);
    // Before: 0.43 m for 1.60 m, 1.56 m for 2.44 m, 1.42 m for 2.29 m.
    EXPECT_NEAR(on_truth.front().step_width, truth.width_m, 0.10);
}

// A level HDL-32 over a descending flight (dev4 r0207), an OS0-128 and an OS1-64 beside wide
// open-riser flights (dev4 r0123, dev6 r0532): each nosing hit in dashes 0.3-0.5 m apart.
INSTANTIATE_TEST_SUITE_P(DevelopmentScenes, DashedNosings,
                         testing::Values(DashedCase{25025, 207, "HDL-32 over a descending flight"},
                                         DashedCase{25025, 123, "OS0-128, wide open-riser flight"},
                                         DashedCase{28028, 532, "OS1-64, wide open-riser flight"}));

}  // namespace
}  // namespace stairmap
