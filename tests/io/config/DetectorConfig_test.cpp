// Loading [detector] from INI text and from the shipped config/default.ini.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <string>

#include "io/config/DetectorConfig.h"
#include "io/config/IniFile.h"

namespace stairmap::io {
namespace {

DetectorConfig load(const std::string& text) {
    mrpt::config::CConfigFileMemory cfg(text);
    return loadDetectorConfig(cfg);
}

std::string errorOf(const std::string& text) {
    try {
        load(text);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(DetectorConfig, MissingSectionKeepsDefaults) {
    const DetectorConfig c = load("[other]\nx = 1\n");
    EXPECT_DOUBLE_EQ(c.params.leaf_size_m, DetectorParams{}.leaf_size_m);
    EXPECT_EQ(c.params.min_steps, DetectorParams{}.min_steps);
    EXPECT_FALSE(c.robot_height_m.has_value());
}

TEST(DetectorConfig, ReadsNumbersIntegersBooleansAndRobotHeight) {
    const DetectorConfig c = load(
        "[detector]\nleaf_size_m = 0.03\nmin_steps = 4\ndetect_descending = false\n"
        "robot_height_m = 0.62\nmax_slope_deg = 55\nsplit_noise_factor = 0\n"
        "max_split_distance_m = 0.04\nmax_level_tread_depth_m = 0\n"
        "min_level_tread_slope_deg = 12\nmin_deep_tread_m = 0.5\nlevel_by_line_spacing = false\n"
        "profile_flights = false\n");
    EXPECT_DOUBLE_EQ(c.params.leaf_size_m, 0.03);
    EXPECT_EQ(c.params.min_steps, 4);
    EXPECT_FALSE(c.params.detect_descending);
    EXPECT_TRUE(c.params.detect_ascending);
    EXPECT_DOUBLE_EQ(c.params.max_slope_deg, 55.0);
    EXPECT_DOUBLE_EQ(c.params.split_noise_factor, 0.0);
    EXPECT_DOUBLE_EQ(c.params.max_split_distance_m, 0.04);
    EXPECT_DOUBLE_EQ(c.params.max_level_tread_depth_m, 0.0);
    EXPECT_DOUBLE_EQ(c.params.min_level_tread_slope_deg, 12.0);
    EXPECT_DOUBLE_EQ(c.params.min_deep_tread_m, 0.5);
    EXPECT_FALSE(c.params.level_by_line_spacing);
    EXPECT_FALSE(c.params.profile_flights);
    ASSERT_TRUE(c.robot_height_m.has_value());
    EXPECT_DOUBLE_EQ(*c.robot_height_m, 0.62);
}

TEST(DetectorConfig, BadValuesNameTheKey) {
    EXPECT_NE(errorOf("[detector]\nleaf_size_m = abc\n").find("leaf_size_m"), std::string::npos);
    EXPECT_NE(errorOf("[detector]\nmin_steps = 2.5\n").find("min_steps"), std::string::npos);
    EXPECT_NE(errorOf("[detector]\ndetect_ascending = maybe\n").find("detect_ascending"),
              std::string::npos);
    EXPECT_NE(errorOf("[detector]\nrobot_height_m = 0.5m\n").find("robot_height_m"),
              std::string::npos);
    // Parses, but out of range: the validation names the field.
    EXPECT_NE(errorOf("[detector]\nmax_step_height_m = 0.05\n").find("max_step_height_m"),
              std::string::npos);
}

TEST(DetectorConfig, ShippedDefaultIniMatchesTheBuiltInDefaults) {
    const auto cfg = openIniFile(std::string(STAIRMAP_SOURCE_DIR) + "/config/default.ini");
    const DetectorConfig c = loadDetectorConfig(*cfg);
    const DetectorParams d;
    EXPECT_DOUBLE_EQ(c.params.leaf_size_m, d.leaf_size_m);
    EXPECT_DOUBLE_EQ(c.params.min_step_height_m, d.min_step_height_m);
    EXPECT_DOUBLE_EQ(c.params.max_step_depth_m, d.max_step_depth_m);
    EXPECT_DOUBLE_EQ(c.params.edge_spill_dz_m, d.edge_spill_dz_m);
    EXPECT_DOUBLE_EQ(c.params.neighbour_walk_m, d.neighbour_walk_m);
    EXPECT_DOUBLE_EQ(c.params.max_collinear_gap_m, d.max_collinear_gap_m);
    EXPECT_DOUBLE_EQ(c.params.split_noise_factor, d.split_noise_factor);
    EXPECT_DOUBLE_EQ(c.params.max_split_distance_m, d.max_split_distance_m);
    EXPECT_DOUBLE_EQ(c.params.max_level_tread_depth_m, d.max_level_tread_depth_m);
    EXPECT_DOUBLE_EQ(c.params.min_level_tread_slope_deg, d.min_level_tread_slope_deg);
    EXPECT_DOUBLE_EQ(c.params.min_deep_tread_m, d.min_deep_tread_m);
    EXPECT_DOUBLE_EQ(c.params.max_double_step_rise_m, d.max_double_step_rise_m);
    EXPECT_DOUBLE_EQ(c.params.tilted_ring_row_height_m, d.tilted_ring_row_height_m);
    EXPECT_EQ(c.params.azimuth_bins, d.azimuth_bins);
    EXPECT_EQ(c.params.min_steps, d.min_steps);
    EXPECT_EQ(c.params.continue_every_other_step, d.continue_every_other_step);
    EXPECT_EQ(c.params.continue_by_next_riser, d.continue_by_next_riser);
    EXPECT_EQ(c.params.ascend_from_below_floor, d.ascend_from_below_floor);
    EXPECT_EQ(c.params.profile_flights, d.profile_flights);
    EXPECT_EQ(c.params.level_by_line_spacing, d.level_by_line_spacing);
    EXPECT_DOUBLE_EQ(c.params.max_ramp_rms_ratio, d.max_ramp_rms_ratio);
    EXPECT_DOUBLE_EQ(c.params.max_descent_start_off_level, d.max_descent_start_off_level);
    EXPECT_DOUBLE_EQ(c.params.dashed_nosing_gap_m, d.dashed_nosing_gap_m);
    EXPECT_EQ(c.params.sparse_line_points, d.sparse_line_points);
    EXPECT_EQ(c.params.few_level_spiral_levels, d.few_level_spiral_levels);
    EXPECT_DOUBLE_EQ(c.params.tread_spiral_cell_m, d.tread_spiral_cell_m);
    EXPECT_DOUBLE_EQ(c.params.tread_spiral_window_m, d.tread_spiral_window_m);
    ASSERT_TRUE(c.robot_height_m.has_value());
    EXPECT_GT(*c.robot_height_m, 0.0);
}

}  // namespace
}  // namespace stairmap::io
