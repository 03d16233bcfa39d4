#pragma once
// Estimation of a staircase's geometry from its ordered step edges (paper Sec. III-D, corrected:
// the paper divides sums of k-1 differences by 2k; here rise and run are least-squares slopes of the
// edge heights / cumulative edge spacings against the step index, which uses every edge).

#include <cstddef>
#include <utility>
#include <vector>

#include "core/Staircase.h"

namespace stairmap {

/// Recomputes step_height, step_depth, step_width, slope_rad, location and heading_rad of `stairs`
/// from `stairs.steps` (ordered outward from the observer's floor). Frame: whatever frame the edges
/// are in, as long as z is up. Rules:
///  - heading: normal of the length-weighted mean edge orientation, pointing from steps.front()
///    towards steps.back() (one edge: the side of the previous heading_rad);
///  - step_height: |slope| of edge height vs. index; step_depth: median pairwise slope of the
///    cumulative spacing over the seen edges (medianPairwiseSlope; least squares over all with
///    fewer than three seen), where the spacing of two edges is their mutual perpendicular XY
///    distance (works for turning spiral steps too);
///  - step_width: median of the longer half of the edge lengths (robust to partially seen edges);
///  - location: centre of steps.front(); slope_rad = atan2(step_height, step_depth).
/// An empty staircase gets all-zero geometry. Cost O(k^2) for k steps (the run's pairs).
void estimateGeometry(Staircase& stairs);

/// Perpendicular XY distance between two edges: mean of the distance of each centre to the other
/// edge's supporting line [m].
double edgeSpacingXY(const StairEdge& a, const StairEdge& b);

/// Extent [lo, hi] of an edge's XY end points projected on the unit direction `lateral` [m].
std::pair<double, double> lateralExtent(const StairEdge& e, const Eigen::Vector2d& lateral);

/// Union of the lateral extents of a flight's edges [m] (empty flight: [+inf, -inf]).
std::pair<double, double> lateralExtent(const Staircase& s, const Eigen::Vector2d& lateral);

/// Least-squares slope of values[i] against the index i (0 for fewer than two values).
double slopeAgainstIndex(const std::vector<double>& values);

/// Largest |v[i] - (a + b x[i])| of the least-squares line through (x[i], v[i]), its slope b into
/// `slope` when given; +inf when x is constant. x and v have the same size.
double lineFitError(const std::vector<double>& x, const std::vector<double>& v,
                    double* slope = nullptr);

/// Theil-Sen slope of values[i] against the index i: the median (of an even count the upper
/// middle one) of (values[j] - values[i]) / (j - i) over the pairs i < j with both `seen`. One
/// value off moves it in few pairs, where it tilts a least-squares slope. slopeAgainstIndex over
/// all values when fewer than `min_pairs` pairs are seen. `seen` has one flag per value.
double medianPairwiseSlope(const std::vector<double>& values, const std::vector<char>& seen,
                           std::size_t min_pairs);

/// Per edge of `steps`: whether the edge was seen (num_points > 0), not put back between seen ones.
std::vector<char> seenEdges(const std::vector<StairEdge>& steps);

/// Height [m] (frame of the staircase) of the surface the flight starts from, as the robot meets
/// it: ascending, the surface one rise under the first nosing (the floor, or a landing or platform
/// the flight rises from); descending, the first edge's own surface (the floor's or a landing's
/// edge). Minus the robot's floor height it is the `start_z` of the detect output: 0 for a flight
/// off the robot's floor. Precondition: !steps.empty(), geometry estimated.
double flightStartZ(const Staircase& s);

/// Unit XY normal of steps[k] pointing outward along the flight (towards the next step; for a
/// turning flight, the step's own normal). Precondition: k < steps.size().
Eigen::Vector2d outwardNormal(const Staircase& s, std::size_t k);

}  // namespace stairmap
