#pragma once
// Nosing heights from the treads behind them. A sparse LiDAR looking up a flight sees mostly the
// riser under each nosing, and the riser's highest ring hit (the edge the top view finds) reads low
// by up to one ring spacing (VLP-16: 7 cm at 2 m, 21 cm at 6 m). A ring that clears a nosing lands
// on the tread behind it, at the nosing's own height: where such tread hits exist, they give the
// edge's true height. Used in sparse-cloud mode (DetectorParams::edge_height_tolerance_m > 0) on
// ascending flights, before RiserHits' raiseLowEdges fits the rest.

#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

struct TreadHeightParams {
    /// [0..1] tread region behind an edge, as fractions of the spacing to the next edge: the
    /// near part holds the edge's own riser hits, the far part the next riser's.
    double near_fraction = 0.15;
    double far_fraction = 0.85;
    /// [m] tread columns are looked for from this far below the edge...
    double below_m = 0.01;
    /// [0..1] ...up to this fraction of the rise above it (the next tread is one rise up)
    double max_raise_fraction = 0.7;
    /// [0..1] the ends of the edge (this fraction of its length each) are left out: walls, a
    /// spiral's column and balusters stand there, and a ring crossing one is as flat as a tread
    double end_fraction = 0.15;
    /// [0..1] a ring crossing a tread spans most of it: the band's points must spread over at
    /// least this fraction of the edge's length (a post, a box top, debris do not)
    double min_spread_fraction = 0.3;
    /// [m] a tread is flat: its points lie within this band
    double flat_band_m = 0.02;
    /// [-] fewest tread points in the band (one ring crossing a tread gives a few)
    int min_points = 4;
    /// [-] fewest treads seen (after dropping those off the others' line) to correct a flight:
    /// two could both be rings on risers above the sensor, which no tread is
    int min_anchors = 3;
    /// [m] a tread farther than this from the line through the others is dropped
    double max_anchor_residual_m = 0.015;
    /// [m] edges are raised only when the treads' line is higher by more than this (noise)
    double min_raise_m = 0.01;
};

/// `edges`: one ascending flight, consecutive steps from the floor upwards, real z; `rise`, `run`:
/// the flight's [m] (run is used behind the last edge, which has no next edge). An edge's tread
/// height is the median of the lowest flat band (debris stands on a tread) of at least min_points
/// points over the region behind it, within its lateral extent, between the edge and
/// max_raise_fraction x rise above it. When at least min_anchors treads lie on one line against
/// the step index, every edge under that line (by less than a rise) is raised onto it. Edges are
/// never lowered; non-finite points are ignored. Returns how many edges were raised.
/// Cost: one pass over the cloud, testing each point in the flight's bounding box against every
/// edge's tread region; then a sort of each region's points.
int raiseEdgesToTreads(const PointCloud& cloud, double rise, double run,
                       std::vector<LineSegment>& edges, const TreadHeightParams& params = {});

}  // namespace stairmap
