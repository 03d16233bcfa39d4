#pragma once
// The first nosing of a descending staircase is the edge of the floor the robot stands on. In the
// floor's z row it competes with every hole of a sparse floor, so instead of being searched for
// among all floor lines it is measured where the first lower nosing predicts it (one run closer).

#include <optional>
#include <vector>

#include "core/LineSegment.h"
#include "core/TopView.h"

namespace stairmap {

struct FloorNosingParams {
    double floor_z = 0.0;          ///< [m]
    double z_tolerance_m = 0.05;   ///< [m] candidate cells within this of the floor
    double search_band_m = 0.08;   ///< [m] half width of the band around the predicted line
    double inlier_band_m = 0.025;  ///< [m] final inliers around the robust offset
    int min_points = 5;            ///< [-] fewer inliers: std::nullopt
};

/// Edge of the floor parallel to `first_lower` (the first nosing below the floor), predicted at
/// distance `run` from it on the robot's side, measured from the back-drop `cells` near the floor:
/// robust (median) offset, then the mean of the inliers. Extent: that of `first_lower`.
std::optional<LineSegment> measureFloorNosing(const std::vector<TopViewCell>& cells,
                                              const LineSegment& first_lower,
                                              const Eigen::Vector2d& heading, double run,
                                              const FloorNosingParams& params);

}  // namespace stairmap
