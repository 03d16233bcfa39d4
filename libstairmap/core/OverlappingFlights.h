#pragma once
// One flight can leave Algorithm 1 (paper Sec. III-C) as two chains: each nosing broken into pieces
// (an occlusion, debris, a railing's shadow, the sparse rows of a far view) gives the search a
// second set of lines at the same levels once the first chain's lines are used. The detector then
// treats the two as two detections of one staircase and applies the paper's multi-detection
// merging (Sec. III-E, Algorithm 2 with Definition 2):
//  1. Split halves side by side: the two chains share stairs (Definition 2 without the overlap
//     gate: same height, collinear, same orientation). One shared stair at most 0.3 m apart, or
//     at least two shared at any lateral gap and at least half of the levels both have (a piece
//     may be skewed): merged (mergeStaircases).
//  2. A chain whose edges mostly lie on the treads of another (same level, within its run, within
//     its lateral extent) is a second, weaker view of the same flight: its edges that are the same
//     stair as the other's edge at that level are fused into it (merge(l_i, l_j) of Algorithm 2),
//     the rest is suppressed. The chain with more steps is kept (Algorithm 1 keeps the longest).
//  3. Halves side by side seen too sparsely for Definition 2: short far edges scatter by 10 deg
//     or more in direction, so edge by edge they are not the same stair. As flights they are:
//     headings within a few degrees, and at two or more levels both have (within the height
//     tolerance) the nosings lie at the same distance along the mean heading, with a lateral gap
//     between the two no wider than a flight's half. The stronger absorbs the other (as in 2).
// Different flights stay apart: a flight beside another is outside its lateral extent, one above
// or below it is at other levels or beyond its treads.

#include <vector>

#include "core/Staircase.h"

namespace stairmap {

struct OverlappingFlightParams {
    /// [-] a chain is a second view of another when at least this fraction of its edges (and at
    /// least two) lie on the other's treads
    double min_on_tread_fraction = 0.5;
    double lateral_margin_m = 0.10;  ///< [m] beyond the other flight's edges, sideways
    /// [-] before a nosing (against the tread's direction), in runs, still on that level
    double before_nosing_runs = 0.5;
    /// [m] an edge is at a level when within max(this, a third of the rise) of its height
    double min_height_tolerance_m = 0.04;
    /// [m] Definition 2's overlap gate for split halves with a single shared stair (negative: gap)
    double split_max_gap_m = 0.3;
    // --- rule 3: halves side by side, compared as flights
    double side_max_heading_diff_deg = 10.0;  ///< [deg] the two flights' headings agree within this
    /// [m] nosings at a shared level lie this close along the mean heading (or 0.15 run if more)
    double side_along_tolerance_m = 0.05;
    double side_max_lateral_gap_m = 0.6;  ///< [m] between the two flights' lateral extents
    int side_min_shared_levels = 2;       ///< [-] levels both have, every one of them agreeing
};

/// Merges split halves and suppresses second views in `found` (same frame, steps ordered outward
/// from the observer's floor) as described above; only staircases of the same direction interact.
/// Returns how many staircases were removed. Cost O(n^2 k^2) for n staircases of k steps.
int mergeOverlappingFlights(std::vector<Staircase>& found,
                            const OverlappingFlightParams& params = {});

/// Are `a` and `b` halves of one flight side by side by rule 3 above? Exposed for tests.
bool sideBySideHalves(const Staircase& a, const Staircase& b, const OverlappingFlightParams& params);

/// Number of `b`'s edges that lie on `a`'s treads (rule 2 above). Exposed for tests.
int edgesOnTreads(const Staircase& a, const Staircase& b, const OverlappingFlightParams& params);

}  // namespace stairmap
