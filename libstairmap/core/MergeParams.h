#pragma once
// Parameters of the merge of two detections of one staircase (paper Sec. III-E): Definition 2
// ("same stair") and the covariance-weighted fusion of two edges (merge(l_i, l_j) of Algorithm 2).

#include <stdexcept>
#include <string>

namespace stairmap {

/// Defaults are the paper's Definition 2 (5 cm / 5 cm / 10 deg) plus the gates and floors this
/// implementation adds. The landmark map relaxes them for pose drift (map/LandmarkParams.h).
struct MergeParams {
    // --- Definition 2: two edges (same frame) are the same stair when ...
    double max_height_diff_m = 0.05;  ///< [m] condition 1: |z_a - z_b| <= this
    /// [m] condition 2: perpendicular XY distance between the LINES <= this (mean of each centre's
    /// distance to the other's line; centres of partial views shift along the edge).
    double max_distance_m = 0.05;
    double max_angle_deg = 10.0;  ///< [deg] condition 3: |alpha_a - alpha_b| <= this
    /// [m] added gate: the edges' extents along the line overlap by at least
    /// min(this, half the shorter edge). Negative = a gap of up to |this| is allowed (the
    /// detector's two halves of one split nosing); positive keeps side-by-side flights apart.
    double min_edge_overlap_m = -0.3;
    // --- merge(l_i, l_j): covariance-weighted fusion of two edges
    /// [m] fused edge ends closer than this are averaged (weighted by observation counts); a
    /// farther end extends the edge (union). Measured choice, see docs/landmarks.md.
    double endpoint_tolerance_m = 0.10;
    double min_sigma_m = 0.003;    ///< [m] floor on an edge's perpendicular sigma (no freezing)
    double min_sigma_deg = 0.2;    ///< [deg] floor on an edge's orientation sigma
    /// [m] rise assumed for level pairing when the first staircase has no rise estimate.
    double default_rise_m = 0.15;

    /// Throws std::invalid_argument naming the first field out of range.
    void validate() const {
        auto require = [](bool ok, const char* field, const char* what) {
            if (!ok) throw std::invalid_argument(std::string("MergeParams.") + field + ": " + what);
        };
        require(max_height_diff_m > 0 && max_height_diff_m < 1, "max_height_diff_m", "must be in (0, 1) m");
        require(max_distance_m > 0 && max_distance_m < 1, "max_distance_m", "must be in (0, 1) m");
        require(max_angle_deg > 0 && max_angle_deg <= 45, "max_angle_deg", "must be in (0, 45] deg");
        require(min_edge_overlap_m > -5 && min_edge_overlap_m < 5, "min_edge_overlap_m",
                "must be in (-5, 5) m");
        require(endpoint_tolerance_m >= 0 && endpoint_tolerance_m < 1, "endpoint_tolerance_m",
                "must be in [0, 1) m");
        require(min_sigma_m > 0 && min_sigma_m < 1, "min_sigma_m", "must be in (0, 1) m");
        require(min_sigma_deg > 0 && min_sigma_deg < 45, "min_sigma_deg", "must be in (0, 45) deg");
        require(default_rise_m > 0 && default_rise_m < 1, "default_rise_m", "must be in (0, 1) m");
    }
};

}  // namespace stairmap
