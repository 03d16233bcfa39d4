#pragma once
// The column of a spiral staircase measured on its own points (issue 10). A spiral's run at mid
// radius needs the column's radius; the nosings' inner ends give it only where a nosing is seen
// to the column, and a far or side view hides their inner parts, so they read long (a spiral's run
// error splits into the inner radius +1.07 cm on average, the step angle -0.10 and the outer
// radius -0.18 cm on the development sets). The column is seen as a vertical cylinder: around the
// fitted axis, the nearest point in each azimuth sector within the flight's heights lies on its
// surface (the treads begin there and only extend outwards). A circle fitted to those points gives
// the radius; the centre absorbs the axis's few cm of error (the sectors' nearest points alone,
// their median distance to the axis, read the radius short by that error and by noise).

#include <Eigen/Core>
#include <optional>

#include "core/PointCloud.h"

namespace stairmap {

struct SpiralColumnParams {
    int sectors = 36;                  ///< [-] azimuth sectors around the axis (10 deg each)
    int min_sectors = 8;               ///< [-] fewer sectors with a point: no fit
    double inlier_m = 0.02;            ///< [m] refits keep the points this close to the circle
    int refits = 2;                    ///< [-] refits on the inliers after the first fit
    double max_centre_shift_m = 0.10;  ///< [m] the circle's centre this close to the axis given
    double min_radius_m = 0.03;        ///< [m] smaller circles are no column
};

struct SpiralColumn {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< [m] XY
    double radius_m = 0.0;                             ///< [m]
};

/// The column around `axis` (robot frame) from the points of `cloud` with z in (z_lo, z_hi) and
/// within `reach` of the axis: the nearest point per sector, an algebraic (Kasa) circle fit to
/// them, refitted on those within inlier_m. Nothing when too few sectors hold a point, the fit is
/// degenerate, or its centre lies farther than max_centre_shift_m from `axis`. Cost: one pass over
/// the cloud.
std::optional<SpiralColumn> fitSpiralColumn(const PointCloud& cloud, const Eigen::Vector2d& axis,
                                            double z_lo, double z_hi, double reach,
                                            const SpiralColumnParams& params = {});

}  // namespace stairmap
