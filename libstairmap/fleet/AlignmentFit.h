#pragma once
// Least-squares 4-DoF transform from matched nosings (the refinement step of the alignment).

#include <vector>

#include "core/Staircase.h"
#include "fleet/AlignmentParams.h"
#include "fleet/Transform4.h"

namespace stairmap::fleet {

/// One nosing seen in both maps: `first` in the first map's frame, `other` in the other's.
/// Both canonical (start = left end facing uphill), so start and end correspond.
struct EdgeCorrespondence {
    StairEdge first;
    StairEdge other;
};

/// 1-sigma uncertainty of an estimated transform.
struct AlignmentSigma {
    double xy_m = 0.0;     ///< [m] largest horizontal standard deviation
    double z_m = 0.0;      ///< [m]
    double yaw_deg = 0.0;  ///< [deg]
};

struct TransformFit {
    Transform4 T_first_other;
    AlignmentSigma sigma;
    double rms_perp_m = 0.0;  ///< [m] rms distance across the nosing lines after the fit
};

/// Weighted least squares over x, y, yaw (Gauss-Newton from the mean edge-direction difference):
/// per pair, the distance across the first nosing's line (params.sigma_perp_m), the offset of the
/// centres along it (params.sigma_lateral_m, widened by the difference in edge length: partial
/// views) and the direction difference (params.sigma_angle_deg); z is the mean height
/// difference. Sigma = the inverse normal matrix scaled by the residuals' reduced chi-square when
/// that exceeds 1 (the a-priori sigmas are a floor). Needs at least one pair (throws
/// std::invalid_argument otherwise). Cost O(n).
TransformFit fitTransform4(const std::vector<EdgeCorrespondence>& pairs,
                           const AlignmentParams& params);

}  // namespace stairmap::fleet
