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

/// Inserts an edge halfway (XY and z) between consecutive edges of a flight that are about two
/// rises apart (1.6-2.4x the median rise of the flight). Inserted edges have num_points = 0 (not
/// seen) and a wide (rho, theta) covariance. `edges` are ordered from the floor outward, z real
/// (descending flights go down). Returns the number of edges inserted.
int fillMissingNosings(std::vector<LineSegment>& edges);

}  // namespace stairmap
