#pragma once
// Algorithm 1 can return one flight as two chains, the second continuing the first where an edge
// read wrong (debris on a tread, a riser hit) broke the chain. Two same-direction staircases of
// one detection are such a pair when the second starts within a few runs beyond the first's last
// edge, along its heading and over the same width. Then either the second's edges lie on the
// first's nosing line (consecutive steps within the height tolerance) and they are appended, or
// they do not and the second is dropped as a corrupted view of the flight's far part: the first
// chain starts one rise from the robot's floor, so it is the anchored one. The second may also
// start on the first's last level (the same nosing read by a second line, debris having ended the
// first chain there): joined when all their edges lie on one rise and run, the shared level keeping
// the longer chain's edge; otherwise the longer chain alone is kept. Where a few steps between the
// two went unseen (riser hits too low to chain, a far VLP-16's rings skipping them: dev5 r0166,
// two of ten; a pitched OS0-128's, four of fifteen: dev5 r0626), the second is still the first's
// continuation when every edge of it lies on the first's nosing line at its own index: the unseen
// steps are put back in between. Such pieces may see different parts of a wide flight's treads
// side by side, and a piece of three short edges may read its heading well off (dev5 r0858: a
// VLP-16 pitched down 24 deg above a 2.1 m wide flight read as seven steps on the left and three
// on the right, 24 deg apart).

#include <vector>

#include "core/Staircase.h"

namespace stairmap {

struct FlightJoinParams {
    double max_heading_diff_deg = 15.0;  ///< [deg] the two headings agree within this
    double max_gap_runs = 2.5;           ///< [-] the second starts at most this many runs beyond
    double min_lateral_overlap = 0.5;  ///< [-] facing edges overlap by this fraction of the shorter
    double height_tolerance_m = 0.04;  ///< [m] appended edges lie this close to the nosing line
    /// [-] steps allowed unseen between the two chains when the second lies on the first's nosing
    /// line (then it may start up to max_unseen_steps + 1.5 runs beyond); 0 = only adjacent. Four:
    /// a pitched OS0-128's rings left four of a 15-step flight's nosings unseen between chains of
    /// four and five (dev5 r0626); 2 -> 4 changed nothing else on dev-dev6 and their negatives.
    int max_unseen_steps = 4;
    /// [deg] the headings of such pieces agree within this when the second has three edges or
    /// fewer (its heading rests on short edges)
    double short_chain_max_heading_diff_deg = 25.0;
    /// [m] such pieces' lateral extents may lie this far apart (side by side on one wide flight)
    double max_lateral_gap_m = 0.10;
};

/// Joins or drops continuing chains in `found` (robot frame, steps ordered outward from the
/// robot's floor). Returns how many staircases were removed. O(n^2 k) for n staircases of k steps.
int joinContinuedFlights(std::vector<Staircase>& found, const FlightJoinParams& params);

}  // namespace stairmap
