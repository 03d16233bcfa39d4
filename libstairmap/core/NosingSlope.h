#pragma once
// A flight's height does not change along its nosings: every tread, riser and nosing is level
// across the flight. A pitched LiDAR's rings crossing a ramp far off its fall line give short
// level pieces along the rings, evenly spaced like nosings (ProfileChains.h: dev5 r1079, a 15 deg
// ramp 6.8 m away read as six steps across a heading 47 deg off its fall line); under such a
// "flight" the surface rises along the pieces' direction. This measures that rise.

#include <optional>
#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

struct NosingSlopeParams {
    int min_points = 20;  ///< [-] fewer points under the flight: no slope measured
    /// [m] the points must spread this far along the nosings (a slope needs a baseline)
    double min_spread_m = 0.4;
    int refits = 2;             ///< [-] refits on the points near the plane
    double inlier_rises = 0.6;  ///< [-] a refit keeps the points this many rises from the plane
};

/// The slope [m/m] along the nosings' direction of the plane fitted (least squares, z against
/// the distance up the flight and along the nosings) to the points of `cloud` between the first
/// and the last edge of `edges` (a straight flight from the floor outward, z real, edges parallel),
/// within their lateral extent and between the first edge's height less a rise and the last's
/// plus a rise. Nothing when too few points, or too little spread, lie there. Non-finite points
/// are ignored. Cost: one pass over the cloud.
std::optional<double> slopeAlongNosings(const PointCloud& cloud,
                                        const std::vector<LineSegment>& edges,
                                        const NosingSlopeParams& params = {});

}  // namespace stairmap
