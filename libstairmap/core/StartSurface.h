#pragma once
// The surface a flight starts from, and the nosing heights it pins. Every nosing of an ascending
// flight lies a whole number of rises above the surface in front of its first riser (the robot's
// floor, a landing, a platform): Z_k = S + (k + 1) R. A sparse LiDAR far from a flight sees only
// riser hits, each up to one ring spacing under its nosing (VLP-16: 17 cm at 5 m, 23 cm at
// 6.6 m). When the ring spacing is close to the rise, RayClearance's bounds pin nothing (every
// step is hit at the same phase) and the chain keeps reading 9-18 cm low, its first edge less than
// a rise above the surface it starts from (dev r0258, dev2 r0070, r0241: a miss and a false
// positive each). The start surface, seen in front of the first riser, fixes the line's offset;
// the edges (lower bounds) and the rays' clearances (upper bounds) then bound the rise alone.

#include <optional>
#include <vector>

#include "core/FlightPoints.h"
#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

struct StartSurfaceParams {
    /// [-] window in front of the first edge, in runs towards the robot: past the riser's own
    /// hits (range noise), within the step in front of it
    double from_runs = 0.2;
    double to_runs = 0.9;
    /// [m] ...reaching at least this far: a far view's rings may miss the floor right in front
    /// of the riser (dev2 r0070: none within 0.5 m, a ring at 0.5-1 m)
    double min_reach_m = 0.8;
    /// [0..1] the ends of the flight (this fraction of its width each) are left out: walls, posts
    double end_fraction = 0.15;
    /// [m] a surface is flat: its points lie within this band
    double band_m = 0.02;
    int min_points = 4;  ///< [-] fewest points in the band
    /// [0..1] the band's points must spread over at least this fraction of the flight's width (one
    /// ring crossing the floor spans most of it; a post, a box top do not)
    double min_spread_fraction = 0.3;
    /// [m] the surface lies at least this below the first edge (a riser hit may lie just above
    /// the surface it rises from: dev2 r0241, 2 cm) ...
    double min_below_edge_m = 0.01;
    /// [m] ... and the window reaches this far below one rise under it: a noisy surface a rise
    /// down is seen whole, not by the upper tail of its noise (a depth camera's floor, dev
    /// r0279: its tail read as a start 3 cm above it)
    double below_rise_margin_m = 0.03;
    /// [m] the first edge reads low when it lies more than this under start + rise (noise of a
    /// measured rise): the edges are then riser hits and move onto the anchored line
    double min_deficit_m = 0.03;
    double tolerance_m = 0.01;  ///< [m] noise allowed on both bounds (RayClearance's tolerance)
    /// [m] the rises inside all bounds must span at most this: their centre is then within half
    /// of it of the truth
    double max_rise_span_m = 0.06;
    double min_rise_m = 0.10;  ///< [m] the anchored rise must be a stair's (condition 1)
    double max_rise_m = 0.30;  ///< [m]
};

/// An axis-aligned box holding startSurfaceHeight's window for these edges, rise and run (empty
/// when there is none): the points of a cloud in it give the same result as the whole cloud. Its
/// top follows the first edge: a caller that raises the edges afterwards widens it upwards.
FlightBox startWindowBox(const std::vector<LineSegment>& edges, double rise, double run,
                         const StartSurfaceParams& params = {});

/// Height [m] of the surface in front of the first edge of `edges` (one ascending flight,
/// consecutive steps, real z; `rise`, `run` [m] the flight's as measured): of the points in the
/// window (from_runs..to_runs runs or min_reach_m in front of the first edge, across the flight's
/// width less the ends, from min_below_edge_m to a rise and below_rise_margin_m under the first
/// edge), the flat band (band_m, in 5 mm bins) holding the most, at least min_points spread across
/// min_spread_fraction of the width; its mean height. The most: the surface a flight starts from
/// fills the area in front of it; a real elevation map smears a riser's foot into a band of
/// intermediate heights there (the ANYmal entrance: 6 cm above the landing), and a noisy floor's
/// tail forms a band of its own. The flight's width: the median of the edges' ends along the
/// first edge (a far flight's first edge, a riser hit, is often a short piece). nullopt when no
/// such band is seen. Non-finite points are ignored. One pass over the cloud, then a sort of the
/// window's points.
std::optional<double> startSurfaceHeight(const PointCloud& cloud,
                                         const std::vector<LineSegment>& edges, double rise,
                                         double run, const StartSurfaceParams& params = {});

/// The surface a flight whose first edge reads low starts from: the one seen in front of it
/// (startSurfaceHeight), else the robot's floor at `floor_z` [m] when it lies in the same band
/// under the first edge. A flight's first nosing lies a rise above the surface it starts from; no
/// surface but the floor lies in that band (a raised platform of a few cm, a pit shallower than a
/// rise are no stairs' starts), so such a first edge is a riser hit of a flight from the floor. A
/// far view's rings may see the floor beside the flight but not in front of it (dev2 r0070).
std::optional<double> lowEdgesStart(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                                    double rise, double run, double floor_z,
                                    const StartSurfaceParams& params = {});

/// Moves `edges` (one ascending flight, consecutive steps, real z; `rise` [m] its measured rise)
/// onto the line Z_k = start_z + (k + 1) b when the first edge reads low (below start_z + rise by
/// more than min_deficit_m). b is the centre of the rises for which every measured edge (num_points
/// > 0: put-back edges are no measurements) lies under its nosing and every finite `upper[k]`
/// (RayClearance's clearance of edge k) above it, both within tolerance_m. Nothing changes when no
/// rise fits, when the fitting rises span more than max_rise_span_m, when no edge has a finite
/// upper bound, or when the rise is no stair's. Returns whether the edges moved.
bool fitEdgesOnStartSurface(double start_z, const std::vector<double>& upper, double rise,
                            std::vector<LineSegment>& edges, const StartSurfaceParams& params = {});

}  // namespace stairmap
