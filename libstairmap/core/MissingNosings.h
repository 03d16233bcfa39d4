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

/// Levels of a chain read from its horizontal spacings where its heights disagree with them. A
/// far level LiDAR sees the risers above its own height only by ring hits, up to a ring spacing
/// under each nosing, and skips risers its rings miss: the chain's heights then step by the ring
/// spacing while its lines stand one, two or three runs apart (dev3 r0288: a VLP-16 7.4 m from
/// 0.20 m rises read as 0.28 m; pairs 1, 3, 2, 1 runs apart, chained as 1, 2, 1, 1 steps). The
/// lines stand on the risers, so their spacing is the step's whatever height the rings hit.
/// When every pair is a whole number (1-3) of one run apart (within xy_tolerance_m; most of them
/// one run), the heights' own levels (fillMissingNosings) leave a pair off that comb by more than
/// min_height_levels_error_m, every pair whose levels differ reaches above riser_hits_above_z_m,
/// and the heights fit a line over the spacing's levels within height_tolerance_m at a rise in
/// [min_rise_m, max_rise_m], the nosings between are put back (linear in XY and z) by spacing.
struct SpacingLevelParams {
    int min_edges = 5;                        ///< [-] seen edges needed: fewer pin no run
    double min_run_m = 0.15;                  ///< [m] the run sought (condition 2) ...
    double max_run_m = 0.45;                  ///< [m]
    double xy_tolerance_m = 0.04;             ///< [m] every edge this close to its run's comb
    double min_height_levels_error_m = 0.06;  ///< [m] the heights' levels off the comb by more
    double height_tolerance_m = 0.08;         ///< [m] riser hits read up to a ring spacing low
    double min_rise_m = 0.09;                 ///< [m] the rise over the spacing's levels ...
    double max_rise_m = 0.32;                 ///< [m]
    /// [deg] every edge this close to the first's direction: a turning chain's spacings are no comb
    double max_turn_deg = 15.0;
    /// [m] the pairs whose levels differ must reach above this height: above the sensor, taken
    /// near the robot frame's origin (as RayClearance does), rings see risers from below and read
    /// them low; below it a LiDAR sees the treads and their heights decide. The cloud does not say
    /// its sensor: an elevation map's or a camera's heights above it are doubted as well
    double riser_hits_above_z_m = 0.0;
    /// [m] fillMissingNosings' min_rise_m, for the heights' own levels
    double height_min_rise_m = 0.0;
};

/// Puts back the nosings a chain stepped over by its spacing (SpacingLevelParams); `edges` in
/// order from the floor outward, z real, all seen. Returns the number put back (0: unchanged).
int fillNosingsBySpacing(std::vector<LineSegment>& edges, const SpacingLevelParams& params = {});

/// A chain whose consecutive edges are each two steps apart (a far LiDAR whose rings alias with
/// the steps sees every other nosing: DetectorParams::max_double_step_rise_m) as the flight: the
/// nosing halfway between each pair put back (unseenNosing). Returns false and leaves `edges`
/// as they are when one of `lines` (real z) lies where a put-back nosing would, within a quarter
/// of the pair's spacing of its line and of its rise of its height and beside its extent: the
/// nosing was seen, the pair is no aliased one.
bool putBackEveryOtherNosing(const std::vector<LineSegment>& lines,
                             std::vector<LineSegment>& edges);

}  // namespace stairmap
