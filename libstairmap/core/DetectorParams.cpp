#include "core/DetectorParams.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/TopView.h"

namespace stairmap {
namespace {

void requireRange(double value, double lo, double hi, const char* field) {
    if (!std::isfinite(value) || value < lo || value > hi) {
        throw std::invalid_argument(std::string("DetectorParams.") + field + " = " +
                                    std::to_string(value) + " is out of range [" +
                                    std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
}

void requireLess(double lo, double hi, const char* field_lo, const char* field_hi) {
    if (!(lo < hi)) {
        throw std::invalid_argument(std::string("DetectorParams.") + field_lo +
                                    " must be smaller than " + field_hi);
    }
}

/// Grid columns beyond 2 max_range / leaf: padding of kMaxNeighbourWalk + 1 empty columns per
/// side plus one spare column for float rounding (TopView.cpp).
constexpr double kGridPadColumns = 2.0 * (kMaxNeighbourWalk + 1) + 1.0;

void requireGridBudget(const DetectorParams& p) {
    if (p.topViewGridBytes() <= static_cast<double>(kMaxTopViewGridBytes)) return;
    const double side = std::sqrt(kMaxTopViewGridBytes / 8.0) - kGridPadColumns;
    const auto decimetres = static_cast<long long>(side * p.leaf_size_m / 2.0 * 10.0);
    throw std::invalid_argument(
        "DetectorParams.max_range_m = " + std::to_string(p.max_range_m) + " with leaf_size_m = " +
        std::to_string(p.leaf_size_m) + " needs a top-view grid of " +
        std::to_string(static_cast<long long>(p.topViewGridBytes() / (1 << 20))) +
        " MiB, more than the budget of " + std::to_string(kMaxTopViewGridBytes >> 20) +
        " MiB: use max_range_m <= " + std::to_string(decimetres / 10) + "." +
        std::to_string(decimetres % 10) + " at this leaf_size_m");
}

}  // namespace

double DetectorParams::topViewGridBytes() const {
    const double side = std::ceil(2.0 * max_range_m / leaf_size_m) + kGridPadColumns;
    return side * side * 8.0;
}

void DetectorParams::validate() const {
    requireRange(leaf_size_m, 0.005, 0.2, "leaf_size_m");
    requireRange(max_range_m, 0.5, 200.0, "max_range_m");
    requireRange(max_ramp_rms_ratio, 0.0, 10.0, "max_ramp_rms_ratio");
    requireRange(max_descent_start_off_level, 0.0, 1.0, "max_descent_start_off_level");
    requireRange(max_height_above_floor_m, 0.3, 50.0, "max_height_above_floor_m");
    requireRange(max_depth_below_floor_m, 0.0, 50.0, "max_depth_below_floor_m");
    requireRange(row_height_m, 0.005, 0.2, "row_height_m");
    if (tilted_ring_row_height_m != 0.0) {
        requireRange(tilted_ring_row_height_m, 0.005, 0.2, "tilted_ring_row_height_m");
        requireLess(row_height_m, tilted_ring_row_height_m, "row_height_m",
                    "tilted_ring_row_height_m");
    }
    requireRange(azimuth_bins, 36, 100000, "azimuth_bins");
    requireRange(edge_min_dz_m, 0.0, 1.0, "edge_min_dz_m");
    requireRange(edge_spill_dz_m, 0.0, 1.0, "edge_spill_dz_m");
    requireRange(neighbour_walk_m, 0.001, 1.0, "neighbour_walk_m");
    requireRange(split_distance_m, 1e-4, 1.0, "split_distance_m");
    requireRange(split_noise_factor, 0.0, 100.0, "split_noise_factor");
    requireRange(max_split_distance_m, split_distance_m, 1.0, "max_split_distance_m");
    requireRange(min_line_points, 2, 100000, "min_line_points");
    requireRange(min_line_length_m, 0.0, 10.0, "min_line_length_m");
    requireRange(max_point_gap_m, 1e-3, 10.0, "max_point_gap_m");
    if (dashed_nosing_gap_m != 0.0) {
        requireRange(dashed_nosing_gap_m, 1e-3, 10.0, "dashed_nosing_gap_m");
        requireLess(max_point_gap_m, dashed_nosing_gap_m, "max_point_gap_m", "dashed_nosing_gap_m");
    }
    if (sparse_line_points != 0) {
        requireRange(sparse_line_points, 2, 100000, "sparse_line_points");
        requireLess(sparse_line_points, min_line_points, "sparse_line_points", "min_line_points");
    }
    if (few_level_spiral_levels != 0)
        requireRange(few_level_spiral_levels, 2, 4, "few_level_spiral_levels");
    if (tread_spiral_cell_m != 0.0) {
        requireRange(tread_spiral_cell_m, 0.02, 0.2, "tread_spiral_cell_m");
        requireRange(tread_spiral_window_m, 0.5, 10.0, "tread_spiral_window_m");
    }
    requireRange(point_sigma_m, 1e-5, 1.0, "point_sigma_m");
    requireRange(merge_chi2, 0.0, 1e6, "merge_chi2");
    requireRange(vertical_merge_dz_m, 0.0, 1.0, "vertical_merge_dz_m");
    requireRange(vertical_merge_dist_m, 0.0, 1.0, "vertical_merge_dist_m");
    requireRange(max_collinear_gap_m, 0.0, 10.0, "max_collinear_gap_m");
    requireRange(floor_tolerance_m, 0.0, 1.0, "floor_tolerance_m");
    requireRange(floor_refine_window_m, 0.0, 2.0, "floor_refine_window_m");
    requireRange(floor_search_radius_m, 0.1, 100.0, "floor_search_radius_m");
    requireRange(min_step_height_m, 0.01, 2.0, "min_step_height_m");
    requireRange(max_step_height_m, 0.01, 2.0, "max_step_height_m");
    requireLess(min_step_height_m, max_step_height_m, "min_step_height_m", "max_step_height_m");
    requireRange(min_step_depth_m, 0.01, 3.0, "min_step_depth_m");
    requireRange(max_step_depth_m, 0.01, 3.0, "max_step_depth_m");
    requireLess(min_step_depth_m, max_step_depth_m, "min_step_depth_m", "max_step_depth_m");
    requireRange(min_slope_deg, 0.0, 90.0, "min_slope_deg");
    requireRange(max_slope_deg, 0.0, 90.0, "max_slope_deg");
    requireLess(min_slope_deg, max_slope_deg, "min_slope_deg", "max_slope_deg");
    if (max_level_tread_depth_m != 0.0)
        requireRange(max_level_tread_depth_m, max_step_depth_m, 3.0, "max_level_tread_depth_m");
    requireRange(min_level_tread_slope_deg, 0.0, min_slope_deg, "min_level_tread_slope_deg");
    if (max_level_tread_depth_m != 0.0)
        requireRange(min_deep_tread_m, min_step_depth_m, max_level_tread_depth_m, "min_deep_tread_m");
    if (max_double_step_rise_m != 0.0)
        requireRange(max_double_step_rise_m, 2 * min_step_height_m, max_step_height_m,
                     "max_double_step_rise_m");
    requireRange(max_parallel_deg, 0.0, 90.0, "max_parallel_deg");
    requireRange(edge_height_tolerance_m, 0.0, 0.1, "edge_height_tolerance_m");
    requireRange(between_overlap_ratio, 0.0, 1.0, "between_overlap_ratio");
    requireRange(min_overlap_ratio, 0.0, 1.0, "min_overlap_ratio");
    requireRange(init_height_factor, 1.0, 20.0, "init_height_factor");
    requireRange(min_steps, 2, 1000, "min_steps");
    requireRange(max_staircases_per_direction, 1, 1000, "max_staircases_per_direction");
    requireGridBudget(*this);
    if (floor_tolerance_m >= min_step_height_m) {
        throw std::invalid_argument(
            "DetectorParams.floor_tolerance_m must be smaller than min_step_height_m");
    }
}

TopViewParams topViewParams(const DetectorParams& params, double floor_z) {
    TopViewParams tp;
    tp.leaf_m = params.leaf_size_m;
    tp.max_range_m = params.max_range_m;
    tp.z_lo = floor_z - params.max_depth_below_floor_m;
    tp.z_hi = floor_z + params.max_height_above_floor_m;
    tp.edge_min_dz_m = params.edge_min_dz_m;
    tp.edge_spill_dz_m = params.edge_spill_dz_m;
    tp.neighbour_walk_m = params.neighbour_walk_m;
    tp.edge_spill_max_dz_m = params.min_step_height_m;
    tp.ground_z_lo = floor_z - params.floor_tolerance_m;
    tp.ground_z_hi = floor_z + params.floor_tolerance_m;
    return tp;
}

}  // namespace stairmap
