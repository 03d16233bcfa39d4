#pragma once
// Nosing heights bounded from both sides by the sensor's rays. A sparse LiDAR looking up a flight
// from afar sees each riser's highest ring hit (the edge the top view finds), which lies at most
// one ring spacing under the nosing: a lower bound. Every point seen *behind* a nosing was reached
// by a ray that cleared it, so where that ray crosses above the nosing's line is an upper bound.
// The nosings of a flight lie on one line against the step index (uniform rise, building codes);
// the rings hit the risers at different heights from step to step, so the intervals of several
// steps pin that line far better than any one of them. Used in sparse-cloud mode on ascending
// flights (DetectorParams::edge_height_tolerance_m > 0), after TreadHeights.
//
// The rays are taken from the robot frame's origin (the cloud carries no sensor pose): a sensor
// mounted dz above it shifts a bound by dz x (distance behind the nosing / range), 1 cm for a
// point 0.1 m behind a nosing 5 m away with the sensor 0.5 m off.

#include <vector>

#include "core/FlightPoints.h"
#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

struct RayClearanceParams {
    /// [m] points at least this far behind an edge's line (its riser hits' noise lies closer:
    /// 4 cm is two sigmas of an HDL-32's 2 cm range noise, and the riser's own top hit a few cm
    /// behind gave dev r0258 a bound at the edge's height, 13 cm under its nosing)...
    double min_behind_m = 0.06;
    /// [-] ...and at most this many runs behind it bound the edge
    double max_behind_runs = 2.0;
    /// [0..1] rays crossing the ends of an edge (this fraction of its length each) are left out:
    /// walls, posts and railings stand there
    double end_fraction = 0.15;
    /// [m] a ray crossing more than this under an edge's own height passed under the tread (an
    /// open riser) or beside the flight: it bounds nothing
    double under_slack_m = 0.01;
    /// [-] the upper bound is the clearance of this many-th lowest ray (one noisy point is not
    /// trusted)
    int clearance_rank = 3;
    /// [m] noise allowed on both bounds when fitting the nosings' line
    double tolerance_m = 0.01;
    /// [-] fewest edges with an upper bound needed to fit the line
    int min_bounded_edges = 3;
    /// [m] the edges move only when the lines inside all bounds (at the fitted rise) span at most
    /// this much: their centre is then within half of it of the truth. When the ring spacing at
    /// the flight's range is close to the rise, every step is hit at the same phase and the bounds
    /// pin nothing (bundled hollow_4: 16 cm); the edges are then left to RiserHits.
    double max_feasible_width_m = 0.10;
    /// [m] the rise is searched this far around the flight's measured rise...
    double rise_search_m = 0.04;
    /// [m] ...in steps of this
    double rise_step_m = 0.001;
};

/// Upper bound [m] of edge k's nosing height from the rays of `cloud` (origin at the robot frame's
/// origin) that cleared it; +infinity when no ray crossed it. `edges`: one ascending flight,
/// consecutive steps, real z; `run` [m] the flight's. Non-finite points are ignored.
double nosingClearance(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                       std::size_t k, double run, const RayClearanceParams& p = {});

/// nosingClearance of every edge, from the points of `cloud` inside `box` only: equal to
/// nosingClearance(points of cloud in box, edges, k, run, p) for each k. Cost: one pass over the
/// cloud, each point in the box tested against every edge (not one pass per edge).
std::vector<double> nosingClearances(const PointCloud& cloud, const FlightBox& box,
                                     const std::vector<LineSegment>& edges, double run,
                                     const RayClearanceParams& p = {});

/// Fits the nosings' line z = a + b * index inside the bounds [edge z, clearance] of every edge
/// (each widened by tolerance_m; rise b within rise_search_m of `rise`) and moves every edge onto
/// it: the centre of the set of lines that satisfy all bounds. Nothing changes when fewer than
/// min_bounded_edges edges have an upper bound, when no line satisfies all bounds or when they
/// span more than max_feasible_width_m. Returns how many edges moved by more than 1 mm.
int fitEdgesToRayClearance(const PointCloud& cloud, double rise, double run,
                           std::vector<LineSegment>& edges, const RayClearanceParams& p = {});

/// The upper bounds fitEdgesToRayClearance fits inside: nosingClearances over the points that
/// can bound the edges (max_behind_runs runs around them, up to two rises above the last).
std::vector<double> edgeClearances(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                                   double rise, double run, const RayClearanceParams& p = {});

/// fitEdgesToRayClearance with the upper bounds already measured (edgeClearances).
int fitEdgesToRayClearance(const std::vector<double>& upper, double rise,
                           std::vector<LineSegment>& edges, const RayClearanceParams& p = {});

}  // namespace stairmap
