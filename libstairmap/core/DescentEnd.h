#pragma once
// The lowest edge of a descending chain. An elevation map cropped beyond a flight's foot ends the
// floor below in a straight line along the crop, at that floor's height, one run or so beyond the
// lowest nosing: a drop into nothing that the descending search reads as the next nosing (its
// tread unseen, as a far nosing's often is). That line runs along the whole crop, several times
// longer than the flight's steps (dev5 r0695: 7.95 m under 0.7-1.8 m edges), and nothing at all
// lies beyond it. Such a lowest edge is no nosing of the flight: kept, it stood as an extra step
// and stretched the partly seen edges to its extent (StaircaseGeometry's completePartialEdges), the
// flight reading 3-8 m wide and off its steps. A real lowest nosing may be the one seen whole
// under nosings seen in pieces (dev6 r0643: 2.3 m under 0.6-0.8 m pieces), but the floor or the
// next tread below it is seen beyond it.

#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

struct DescentEndParams {
    /// [-] the lowest edge is asked when longer than this many times the longest of the others
    /// (the dev sets' crop lines read 3-5 times)
    double max_length_ratio = 3.0;
    /// [m] ... and dropped when no more than max_points_beyond points, at any height, lie this
    /// far beyond it (away from the edge above), ...
    double beyond_from_m = 0.05;
    double beyond_to_m = 0.5;
    /// [0..1] ... along its middle (this fraction of its length left out at each end)
    double end_fraction = 0.15;
    int max_points_beyond = 3;  ///< [-] a few stray points are no surface
};

/// Drops the last edge of `edges` (a descending chain, real z, outward from the robot, two edges
/// or more) when it is longer than params.max_length_ratio times every other edge and `cloud`
/// shows nothing beyond it, as above. Returns whether it did. Cost: one pass over the cloud when
/// the length test passes, none otherwise. Non-finite points are ignored.
bool dropCropLineEnd(const PointCloud& cloud, std::vector<LineSegment>& edges,
                     const DescentEndParams& params = {});

}  // namespace stairmap
