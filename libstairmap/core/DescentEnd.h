#pragma once
// The lowest edge of a descending chain. An elevation map cropped beyond a flight's foot ends the
// floor below in a straight line along the crop, at that floor's height, one run or so beyond the
// lowest nosing: a drop into nothing that the descending search reads as the next nosing (its
// tread unseen, as a far nosing's often is). That line runs along the whole crop, several times
// longer than the flight's steps (dev5 r0695: 7.95 m under 0.7-1.8 m edges), where the steps of
// one flight are about equally wide (building codes). Such a lowest edge is no nosing of the
// flight: kept, it stood as an extra step and stretched the partly seen edges to its extent
// (StaircaseGeometry's completePartialEdges), the flight reading 3-8 m wide and off its steps.

#include <vector>

#include "core/LineSegment.h"

namespace stairmap {

struct DescentEndParams {
    /// [-] the lowest edge is dropped when longer than this many times the longest of the others
    /// (the dev sets' crop lines read 3-5 times, a flight's edges differ by less than 2: pieces
    /// are shorter, not longer)
    double max_length_ratio = 3.0;
};

/// Drops the last edge of `edges` (a descending chain, outward from the robot, two edges or more)
/// when it is longer than params.max_length_ratio times every other edge. Returns whether it did.
bool dropCropLineEnd(std::vector<LineSegment>& edges, const DescentEndParams& params = {});

}  // namespace stairmap
