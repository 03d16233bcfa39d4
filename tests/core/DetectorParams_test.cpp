// Parameter validation: defaults are valid, every bad value is rejected naming its field.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "core/DetectorParams.h"
#include "core/StairDetector.h"

namespace stairmap {
namespace {

TEST(DetectorParams, DefaultsAreValidAndFollowThePaper) {
    const DetectorParams p;
    EXPECT_NO_THROW(p.validate());
    EXPECT_DOUBLE_EQ(p.leaf_size_m, 0.025);
    EXPECT_DOUBLE_EQ(p.min_step_height_m, 0.11);
    EXPECT_DOUBLE_EQ(p.max_step_height_m, 0.30);
    EXPECT_DOUBLE_EQ(p.min_step_depth_m, 0.15);
    EXPECT_DOUBLE_EQ(p.max_step_depth_m, 0.45);
    EXPECT_DOUBLE_EQ(p.min_slope_deg, 20.0);  // paper: 25; shallow entrance flights (issue 10)
    EXPECT_DOUBLE_EQ(p.max_slope_deg, 60.0);
    EXPECT_DOUBLE_EQ(p.max_parallel_deg, 45.0);  // paper: 10; narrow spirals (DetectorParams.h)
    EXPECT_EQ(p.min_steps, 4);
    EXPECT_DOUBLE_EQ(p.init_height_factor, 3.5);  // 2.5 missed flights with hidden first steps
}

TEST(DetectorParams, TopViewGridBudgetBoundsRangeOverLeaf) {
    // Worst case (2 r / leaf + 19)^2 columns of 8 bytes <= 128 MiB: r / leaf <= 2038.
    DetectorParams p;
    EXPECT_NEAR(p.topViewGridBytes(), 819.0 * 819.0 * 8.0, 1.0);  // 10 m at 2.5 cm: 5.4 MB
    for (const auto& [range, leaf] : {std::pair{50.9, 0.025}, std::pair{20.3, 0.01}, std::pair{10.1, 0.005},
                                      std::pair{200.0, 0.2}}) {
        p.max_range_m = range;
        p.leaf_size_m = leaf;
        EXPECT_NO_THROW(p.validate()) << range << " m at " << leaf;
        EXPECT_LE(p.topViewGridBytes(), double(kMaxTopViewGridBytes));
        p.max_range_m = range * 1.01;  // just beyond (or beyond the 200 m range limit)
        EXPECT_THROW(p.validate(), std::invalid_argument) << range * 1.01 << " m at " << leaf;
    }
}

TEST(DetectorParams, GridBudgetErrorSaysWhatFits) {
    DetectorParams p;
    p.max_range_m = 200;
    try {
        p.validate();
        FAIL() << "accepted a 2 GB grid";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("max_range_m = 200"), std::string::npos) << what;
        EXPECT_NE(what.find("leaf_size_m"), std::string::npos) << what;
        EXPECT_NE(what.find("max_range_m <= 50.9"), std::string::npos) << what;
    }
}

struct BadValue {
    std::string field;
    std::function<void(DetectorParams&)> spoil;
};

class RejectsBadValue : public testing::TestWithParam<BadValue> {};

TEST_P(RejectsBadValue, NamesTheField) {
    DetectorParams p;
    GetParam().spoil(p);
    try {
        p.validate();
        FAIL() << "accepted a bad " << GetParam().field;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(GetParam().field), std::string::npos) << e.what();
    }
    EXPECT_THROW(StairDetector{p}, std::invalid_argument);
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

INSTANTIATE_TEST_SUITE_P(
    Fields, RejectsBadValue,
    testing::Values(
        BadValue{"leaf_size_m", [](DetectorParams& p) { p.leaf_size_m = 0.0; }},
        BadValue{"leaf_size_m", [](DetectorParams& p) { p.leaf_size_m = kNaN; }},
        BadValue{"azimuth_bins", [](DetectorParams& p) { p.azimuth_bins = 3; }},
        BadValue{"min_line_points", [](DetectorParams& p) { p.min_line_points = 1; }},
        BadValue{"max_step_height_m", [](DetectorParams& p) { p.max_step_height_m = 0.05; }},
        BadValue{"min_slope_deg", [](DetectorParams& p) { p.min_slope_deg = 70; }},
        BadValue{"point_sigma_m", [](DetectorParams& p) { p.point_sigma_m = -1; }},
        BadValue{"split_noise_factor", [](DetectorParams& p) { p.split_noise_factor = -1; }},
        BadValue{"max_split_distance_m",  // below the fixed d_p it would raise
                 [](DetectorParams& p) { p.max_split_distance_m = 0.02; }},
        BadValue{"floor_tolerance_m", [](DetectorParams& p) { p.floor_tolerance_m = 0.2; }},
        BadValue{"max_level_tread_depth_m",  // below the usual run bound
                 [](DetectorParams& p) { p.max_level_tread_depth_m = 0.3; }},
        BadValue{"tilted_ring_row_height_m",  // rows no taller than the first pass's
                 [](DetectorParams& p) { p.tilted_ring_row_height_m = 0.02; }},
        BadValue{"tilted_ring_row_height_m",
                 [](DetectorParams& p) { p.tilted_ring_row_height_m = 0.5; }},
        BadValue{"max_double_step_rise_m",  // under two of the smallest rises
                 [](DetectorParams& p) { p.max_double_step_rise_m = 0.15; }},
        BadValue{"max_double_step_rise_m",  // beyond condition 1's bound
                 [](DetectorParams& p) { p.max_double_step_rise_m = 0.5; }},
        BadValue{"min_level_tread_slope_deg",  // above the usual slope bound
                 [](DetectorParams& p) { p.min_level_tread_slope_deg = 30; }},
        BadValue{"min_deep_tread_m",  // deeper than the deep search reaches
                 [](DetectorParams& p) { p.min_deep_tread_m = 0.7; }},
        BadValue{"min_steps", [](DetectorParams& p) { p.min_steps = 1; }},
        BadValue{"max_ramp_rms_ratio", [](DetectorParams& p) { p.max_ramp_rms_ratio = -0.1; }},
        BadValue{"max_descent_start_off_level",
                 [](DetectorParams& p) { p.max_descent_start_off_level = 1.5; }},
        BadValue{"max_descent_start_off_level",
                 [](DetectorParams& p) { p.max_descent_start_off_level = -0.1; }},
        BadValue{"dashed_nosing_gap_m",  // gaps no longer than the first pass's
                 [](DetectorParams& p) { p.dashed_nosing_gap_m = 0.15; }},
        BadValue{"dashed_nosing_gap_m", [](DetectorParams& p) { p.dashed_nosing_gap_m = -1; }},
        BadValue{"sparse_line_points",  // no fewer points than the first pass's lines
                 [](DetectorParams& p) { p.sparse_line_points = 5; }},
        BadValue{"sparse_line_points", [](DetectorParams& p) { p.sparse_line_points = 1; }},
        BadValue{"sparse_line_points", [](DetectorParams& p) { p.sparse_line_points = -1; }},
        BadValue{"few_level_spiral_levels",  // the spiral search itself asks five
                 [](DetectorParams& p) { p.few_level_spiral_levels = 5; }},
        BadValue{"few_level_spiral_levels",
                 [](DetectorParams& p) { p.few_level_spiral_levels = 1; }},
        BadValue{"tread_spiral_cell_m", [](DetectorParams& p) { p.tread_spiral_cell_m = 0.01; }},
        BadValue{"tread_spiral_cell_m", [](DetectorParams& p) { p.tread_spiral_cell_m = 0.5; }},
        BadValue{"tread_spiral_cell_m", [](DetectorParams& p) { p.tread_spiral_cell_m = -0.05; }},
        BadValue{"tread_spiral_window_m", [](DetectorParams& p) { p.tread_spiral_window_m = 0.1; }},
        BadValue{"tread_spiral_window_m",  // the surface's memory
                 [](DetectorParams& p) { p.tread_spiral_window_m = 50; }},
        // Top-view grid over the memory budget (the far-extent case of issue 8).
        BadValue{"max_range_m", [](DetectorParams& p) { p.max_range_m = 200; }},
        BadValue{"max_range_m",
                 [](DetectorParams& p) {
                     p.max_range_m = 21;
                     p.leaf_size_m = 0.01;
                 }}),
    [](const testing::TestParamInfo<BadValue>& param_info) {
        return param_info.param.field + "_" + std::to_string(param_info.index);
    });

}  // namespace
}  // namespace stairmap
