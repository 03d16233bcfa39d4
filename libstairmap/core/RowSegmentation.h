#pragma once
// Segmentation, paper Sec. III-B: every row of the cylindrical array is a circular 2D scan; it is
// cut at gaps, split by iterative end-point fit (threshold d_p), each part fitted by weighted least
// squares (with covariance) and adjacent parts merged when their (rho, theta) agree (Mahalanobis).
// The row is circular: a line crossing the +-180 deg seam is extracted whole.

#include <vector>

#include "core/CylindricalRows.h"
#include "core/LineSegment.h"

namespace stairmap {

/// (RowLinesCache shares a segmentation between requests equal in every field but
/// min_line_points: a field added here must be compared there, in sameButPoints.)
struct SegmentationParams {
    double split_distance_m = 0.03;   ///< [m] d_p
    int min_line_points = 5;          ///< [-] N_min
    double min_line_length_m = 0.20;  ///< [m]
    double max_point_gap_m = 0.20;    ///< [m]
    double point_sigma_m = 0.01;      ///< [m]
    double merge_chi2 = 9.21;         ///< [-]
};

/// Appends the lines of every row of `rows` to `lines`. Cost O(n log n) in the row's points.
void segmentRows(const CylindricalRows& rows, const SegmentationParams& params,
                 std::vector<LineSegment>& lines);

/// Segments one row given as XY(Z) arrays in azimuth order, treating it as circular.
/// Exposed for tests.
void segmentCircularRow(const float* x, const float* y, const float* z, int n,
                        const SegmentationParams& params, std::vector<LineSegment>& lines);

}  // namespace stairmap
