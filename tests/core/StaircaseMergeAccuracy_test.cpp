// Accuracy of the merge over many noisy partial views of one known flight (seeded noise), and the
// measurement behind the end point rule: averaging near ends vs the union of all extents.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/StaircaseCanonical.h"
#include "core/StaircaseMerge.h"
#include "core/SyntheticStairs.h"

namespace stairmap {
namespace {

struct FusedErrors {
    double rise = 0, run = 0, width = 0, location = 0, worst_edge_perp = 0;
};

/// Merges 30 noisy 4-edge views (half of them seen from the top) one after the other, as the
/// landmark map does, and measures the result against the truth.
FusedErrors fuseNoisyViews(unsigned seed, double endpoint_tolerance_m) {
    test::FlightTruth truth;
    truth.origin_xy = {-3.0, 1.0};
    truth.heading_rad = -0.8;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> first_step(0, truth.num_steps - 4);
    MergeParams params;
    params.endpoint_tolerance_m = endpoint_tolerance_m;
    std::optional<WeightedStaircase> fused;
    for (int k = 0; k < 30; ++k) {
        test::ViewSpec v;
        v.first = k == 0 ? 0 : first_step(rng);
        v.last = v.first + 3;
        v.descending = (k % 2) == 1;
        v.sigma_perp = 0.015;
        v.sigma_theta = 0.02;
        v.sigma_z = 0.01;
        v.sigma_end = 0.02;
        const Staircase view = *canonicalStaircase(test::makeDetection(truth, v, rng));
        const WeightedStaircase w{view, std::vector<int>(view.steps.size(), 1)};
        fused = fused ? mergeCanonical(*fused, w, params, StepAnchor::AssociatedElsewhere) : w;
    }
    const Staircase& s = fused->stairs;
    FusedErrors e;
    e.rise = std::abs(s.step_height - truth.rise);
    e.run = std::abs(s.step_depth - truth.run);
    e.width = std::abs(s.step_width - truth.width);
    e.location = (s.location - truth.edgeCentre(0)).norm();
    for (const StairEdge& edge : s.steps) {
        const int level = static_cast<int>(std::lround(edge.centre().z() / truth.rise)) - 1;
        const Eigen::Vector2d d = (edge.centre() - truth.edgeCentre(level)).head<2>();
        e.worst_edge_perp = std::max(e.worst_edge_perp, std::abs(d.dot(truth.uphill())));
    }
    return e;
}

class MergeAccuracy : public ::testing::TestWithParam<unsigned> {};

TEST_P(MergeAccuracy, ThirtyNoisyPartialViewsConvergeOnTheTruth) {
    const FusedErrors e = fuseNoisyViews(GetParam(), MergeParams{}.endpoint_tolerance_m);
    std::printf("seed %u: rise %.4f run %.4f width %.4f location %.4f worst edge %.4f m\n",
                GetParam(), e.rise, e.run, e.width, e.location, e.worst_edge_perp);
    // Single views have sigma 1.5 cm across the edge, 1 cm in z and 2 cm per end.
    EXPECT_LT(e.rise, 0.003);
    EXPECT_LT(e.run, 0.005);
    EXPECT_LT(e.width, 0.02);
    EXPECT_LT(e.location, 0.015);
    EXPECT_LT(e.worst_edge_perp, 0.015);
}

TEST_P(MergeAccuracy, UnionOfNoisyEndsOverstatesTheWidthAveragingDoesNot) {
    const FusedErrors averaged = fuseNoisyViews(GetParam(), 0.10);
    const FusedErrors united = fuseNoisyViews(GetParam(), 0.0);
    std::printf("seed %u: width error averaged ends %.4f m, union of extents %.4f m\n", GetParam(),
                averaged.width, united.width);
    // Each end is the maximum of ~12 noisy ends under the union: about +2 sigma per end.
    EXPECT_GT(united.width, 0.04);
    EXPECT_LT(averaged.width, 0.5 * united.width);
}

INSTANTIATE_TEST_SUITE_P(Seeds, MergeAccuracy, ::testing::Values(21u, 22u, 23u));

}  // namespace
}  // namespace stairmap
