#pragma once
// Whole flights (issue 10): Algorithm 1's extension may step over one unseen nosing (its line too
// short or broken in the sparse rows of a far or oblique view, StairSearch.cpp). The flight still
// has that step: it is put back, halfway between its neighbours, so the step count, the per-index
// rise fit and the merging with other views stay right.

#include <vector>

#include "core/LineSegment.h"

namespace stairmap {

/// A nosing that was not seen, put back from its end points and height: Hessian form (rho >= 0),
/// num_points = 0 and a wide (rho, theta) covariance (5 cm, 0.1 rad), so fusion weighs it little.
LineSegment unseenNosing(const Eigen::Vector2d& start, const Eigen::Vector2d& end, double z);

/// The unseen nosing halfway (XY and z) between edges a and b, its end points paired by their
/// position along a.
LineSegment halfwayNosing(const LineSegment& a, const LineSegment& b);

/// Inserts an edge halfway (XY and z) between consecutive edges of a flight that are about two
/// rises apart (1.6-2.4x the median rise of the flight). Inserted edges have num_points = 0 (not
/// seen) and a wide (rho, theta) covariance. `edges` are ordered from the floor outward, z real
/// (descending flights go down). Returns the number of edges inserted.
/// A pair whose horizontal spacing is one run (0.75-1.33x the median spacing) keeps no step
/// between when its heights are not to be trusted over its spacing: the chain's median rise is
/// under `min_rise_m` (condition 1: riser hits of a far LiDAR, read low by up to a ring spacing),
/// or both edges are at least 1 m long (their spacing is pinned; short far pieces scatter in
/// direction by 10 deg and more, and there the heights decide). On dev2 this took rise / run MAE
/// 0.25 / 0.59 -> 0.21 / 0.49 cm (r0098, r0151, r0170 had a nosing put back mid-tread).
int fillMissingNosings(std::vector<LineSegment>& edges, double min_rise_m = 0.0);

/// A chain whose consecutive edges are each two steps apart (a far LiDAR whose rings alias with
/// the steps sees every other nosing: DetectorParams::max_double_step_rise_m) as the flight: the
/// nosing halfway between each pair put back (unseenNosing). Returns false and leaves `edges`
/// as they are when one of `lines` (real z) lies where a put-back nosing would, within a quarter
/// of the pair's spacing of its line and of its rise of its height and beside its extent: the
/// nosing was seen, the pair is no aliased one.
bool putBackEveryOtherNosing(const std::vector<LineSegment>& lines,
                             std::vector<LineSegment>& edges);

}  // namespace stairmap
