// Widths of flights whose nosings a far ring hits in dashes (StepExtentParams::max_open_gap_m):
// scenes of the randomised benchmark's development sets where the steps ended at the first hole
// between two dashes and the flight read 0.9-1.2 m narrow. Each is now read within 10 cm of its
// true width. Truth from the scene description.

#include <gtest/gtest.h>

#include "support/BenchmarkScenes.h"
#include "support/SceneExpectations.h"

namespace stairmap {
namespace {

class DashedNosings : public testing::TestWithParam<test::NamedScene> {};

TEST_P(DashedNosings, TheFlightIsReadAsWideAsItIs) {
    const auto found = test::onlyFlightReadOnTruth(GetParam());
    ASSERT_TRUE(found.has_value());
    // Before: 0.43 m for 1.60 m, 1.56 m for 2.44 m, 1.42 m for 2.29 m.
    EXPECT_NEAR(found->first.step_width, found->second.width_m, 0.10);
}

// A level HDL-32 over a descending flight (dev4 r0207), an OS0-128 and an OS1-64 beside wide
// open-riser flights (dev4 r0123, dev6 r0532): each nosing hit in dashes 0.3-0.5 m apart.
INSTANTIATE_TEST_SUITE_P(
    DevelopmentScenes, DashedNosings,
    testing::Values(test::NamedScene{25025, 207, "HDL-32 over a descending flight"},
                    test::NamedScene{25025, 123, "OS0-128, wide open-riser flight"},
                    test::NamedScene{28028, 532, "OS1-64, wide open-riser flight"}));

}  // namespace
}  // namespace stairmap
