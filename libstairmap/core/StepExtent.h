#pragma once
// Width of each step across the full visible extent of its tread, and what bounds each side.
// A nosing line found in one z row is often a piece of the step (a gap in a far row, debris, the
// end hidden by a stairwell wall's top), so the paper's width (mean edge length, Sec. III-D)
// reads short. Here every tread is measured in the cloud itself: from the found edge, sideways
// over the points lying on the tread (at its height, within its run) or on its nosing line until a
// wall or a gap; then beyond
// each end the side is classified:
//  - Wall:   points rising above the tread just beyond its end (a wall, a railing's posts);
//  - Open:   no such points, but the floor or a drop (points well below the tread) seen there;
//  - Unseen: no points beyond the end: the view does not cover it, the width may be short.
// A side unseen on the steps is a wall after all when a wall or railing is seen beyond the hole
// in line on several steps (the tread between hidden: a LiDAR's blind cone close below it, the
// nearer steps over a descending flight); the steps then reach it.
// Edges are lengthened to the measured extent (never shortened), then the geometry re-estimated.
// A straight flight's width runs between its two sides, each placed where the steps' ends on it
// lie in one frame across the flight (different steps may see the two ends): at the outer quartile
// of the steps' ends when both sides are bounded (at the outermost where they scatter), at the
// outermost when a side is unseen (every end reads short there). A turning flight's width comes
// from its steps' own widths (the widest with a side unseen, else their upper quartile).

#include "core/PointCloud.h"
#include "core/Staircase.h"

namespace stairmap {

struct StepExtentParams {
    double bin_m = 0.025;            ///< [m] lateral resolution (the top view's column size)
    double tread_dz_m = 0.03;        ///< [m] a point is on the tread within this of its height
    double tread_from_runs = 0.15;   ///< [-] tread window starts this far (in runs) from the nosing
    double tread_to_runs = 0.85;     ///< [-] ... and ends here (away from the riser of the next)
    double max_gap_m = 0.10;  ///< [m] the tread continues across any hole up to this ...
    /// [m] ... and across holes up to side_band_m when nothing in them rises above the tread (a
    /// sparse or shadowed tread; a wall or a box stops the walk after max_gap_m); also the band
    /// beyond an end that is looked at for its side
    double side_band_m = 0.30;
    /// [m] On a straight flight (dashed_max_turn_deg), holes with nothing above are crossed up to
    /// this: a far ring often hits a step only on its nosing, in short dashes 0.3-1 m apart (dev4
    /// r0207: a descending flight 1.60 m wide read 0.43 m). Width MAE over dev-dev6 7.57 -> 7.07
    /// cm with 1.3 (0.3 = side_band_m before; 0.8: 7.37, 1.0: 7.12, 1.7: 7.20; 2.5: 7.21 and a
    /// flight lost; measured with every flight walked so).
    double max_open_gap_m = 1.3;
    /// [deg] ... where no two found edges of the flight are more than this apart (as lines): a
    /// spiral's radial nosing lines run on across its column and past its rim (bundled spiral_0:
    /// two steps read 1.50 m for 1.28 m). Straight flights' fits differ by up to ~10 deg; 30 / 45 /
    /// 60: width MAE 7.17 / 7.07 / 7.05 cm over dev-dev6, bundled clouds 2.19 cm with each.
    double dashed_max_turn_deg = 45.0;
    double max_extension_m = 2.5;    ///< [m] beyond the found edge, on each side
    double side_dz_m = 0.08;         ///< [m] rising above / dropping below the tread by this
    /// [-] points within this many runs of the found nosing line, at the tread's height, lie on
    /// the nosing: a far LiDAR ring often hits a step only there, the tread window stays empty
    /// (dev2 r0276: 0.67 m read for 1.26 m). Such a bin counts as tread only when nothing rises
    /// above the nosing line there (a wall, a column) and its tread window holds no point at all
    /// (a stringer beside the flight puts its top there). On a straight flight, after a hole with
    /// nothing above, such a bin resumes the tread on its own (one ring's dash, max_open_gap_m); a
    /// tread bin needs another next to it.
    double nosing_band_runs = 0.2;
    /// Offer each point only to the treads whose windows may hold it (indexed along the flight:
    /// the same result, 2x fewer instructions on the randomised sets). false offers every point
    /// to every tread: the reference the index is tested equal to.
    bool index_along_flight = true;
    /// [m] on an ascending flight, points in the tread window's last this much before the next
    /// nosing and less than 1.5 rises above the tread are the next step's front (its riser, an
    /// open tread's edge), spread there by range noise along a far flight: not a wall
    double next_front_margin_m = 0.08;
    /// [m] A side no step sees bounded is bounded after all by a wall or railing seen beyond a
    /// hole up to this wide (the tread between hidden: a LiDAR's blind cone close below it, the
    /// nearer steps over a descending flight) ...
    double max_bridge_m = 1.2;
    /// [-] ... when at least this many steps, and half of those whose side was unseen, see it ...
    int min_bridge_steps = 3;
    /// [m] ... at the same place across the flight within this (a wall runs along the flight;
    /// furniture beside it does not rise above three treads in line).
    double bridge_agree_m = 0.10;
    /// [deg] when every edge's direction is within this of the flight's mean, the treads are
    /// scanned along that mean: one fit's angle error tilts its window off the nosing line and
    /// into the next step. Fits err by a few degrees; a spiral turns 15 deg or more a step.
    /// (Development sets, width MAE: 6.30 / 8.04 / 6.87 -> 6.31 / 7.78 / 6.40 cm; 5 deg: 6.37 /
    /// 7.80 / 6.64; 12: 6.29 / 7.96 / 6.40.) 0 scans each along its own edge.
    double common_direction_max_deg = 8.0;
    /// [m] With both sides bounded, each side of a straight flight is placed at the outer quartile
    /// of its steps' ends, or at the outermost end when that quartile lies more than this beyond
    /// their median: the ends scatter where most steps stop short of the side at gaps in their
    /// treads (far rows, open risers seen through; dev r0049: 1.60 m read for 1.94 m). Width MAE
    /// dev / dev2 / dev3 6.22 / 7.53 / 6.78 -> 5.94 / 7.43 / 6.63 cm; 0.05 m: 5.97 / 7.32 / 6.73;
    /// 0.20 m: 6.19 / 7.45 / 6.64; the second outermost end instead (in that run also on the
    /// unseen sides whose ends scatter): 7.59 / 9.71 / 8.19.
    double side_spread_m = 0.10;
};

/// Measures every step of `stairs` (robot frame, as detected) in `cloud` as described above and
/// sets the edges' extents, left_side / right_side (majority over the steps where that side was
/// seen, unseen when most steps saw nothing) and the geometry. The floor's own edge (first edge
/// of a descending flight) and the landing's (last of an ascending one) border whole floors and
/// are neither measured nor voted on. Cost: one pass over the cloud per staircase plus
/// O(points near it x steps reaching them): one or two steps per point on a straight flight.
void measureStepExtents(const PointCloud& cloud, Staircase& stairs,
                        const StepExtentParams& params = {});

}  // namespace stairmap
