#pragma once
// Height noise of the floor the robot stands on, measured in the cloud itself. The segmentation's
// split distance d_p (paper Sec. III-B) must exceed the scatter of a row's candidate columns, or a
// noisy nosing breaks into pieces too short to be lines. A LiDAR's floor points 2.5-4.5 m away
// scatter by 0.2-0.9 cm (range noise of about 1 cm seen at a grazing angle); a depth camera's,
// whose range noise grows with the range squared, by 0.7-3.2 cm (dev, dev2 and check sets).

#include "core/PointCloud.h"

namespace stairmap {

struct FloorNoiseParams {
    double inner_radius_m = 2.5;  ///< [m] the ring of floor looked at: near enough to be seen ...
    double outer_radius_m = 4.5;  ///< [m] ... and far enough for a depth camera's noise to show
    double band_m = 0.05;         ///< [m] points within this of the floor height are floor points
    int min_points = 50;          ///< [-] fewer floor points in the ring: no measurement (0)
    /// [-] every k-th point is looked at, k chosen so that about this many are: a sigma needs a
    /// few hundred samples, not a dense cloud's 100k (which cost 0.3-0.5 ms per cloud)
    int max_points_visited = 16384;
};

/// Robust standard deviation [m] of the heights of the floor points (within band_m of floor_z)
/// whose XY distance from the robot lies in the ring: 1.2533 x their mean absolute deviation from
/// the median, the sigma of a Gaussian (the mean deviation, unlike the median one, resolves clouds
/// stored in 2 mm steps). 0 when the ring holds fewer than min_points of the points looked at.
/// Non-finite points are skipped. Cost: at most about max_points_visited points looked at, plus
/// a selection over the ring's floor points among them.
double floorHeightNoise(const PointCloud& cloud, double floor_z, const FloorNoiseParams& params = {});

}  // namespace stairmap
