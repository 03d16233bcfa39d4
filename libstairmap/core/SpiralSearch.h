#pragma once
// Spiral staircases found by their axis (issue 10). Algorithm 1 (StairSearch) chains a nosing to
// the next one only when the two are near-parallel and the upper one lies one run further along the
// lower one's normal. A spiral's wedge nosings are radial lines around the central column, each
// turned by the step angle (15-65 deg) from the one below, and a sparse or side view often sees
// only every other one (two steps turn up to 130 deg). Their common property is the axis: every
// nosing's line passes (within a few cm) through it, its inner end near the column, and its angle
// around the axis grows linearly with its height (a helix). This search looks for that directly,
// on the lines of both drop directions (a wedge seen from its side reads as either). A tread's back
// edge (where the next wedge rises) reads as a drop too when that wedge's top is unseen (above a
// level LiDAR): those lines lie on a second helix one step angle ahead and are turned back onto
// their tread's nosing.
//
// Per pair of lines one to two rises apart and not parallel: their lines' intersection is an axis
// candidate when it lies near the inner end of both; the lines through it (radial, not straddling
// it) whose angle around it matches the pair's helix are its inliers. The axis is refitted to
// them, nosings and back edges are told apart by refitting the helix to both (each at its own
// height) until every line sits on the nearer one, their levels must lie on one rise (a missing
// level or two is put back, turning by as many step angles as it rises), the step angle and the
// run at mid radius must be a stair's. The candidate with the most levels (then seen levels, then
// lines) wins; its lines are removed and the search repeats. A candidate whose lines hold
// min_strict_levels levels but fewer than min_seen_levels (a close view: the column hides the inner
// part of the lower nosings) has its empty levels next to or between them filled by lines under
// looser bounds that lie on its helix's angle and rise; they never move its axis or helix.
//
// Where no nosing helix is found, an elevation map cropped at the spiral may show only the treads'
// outer rims: each a chord of the outer arc, whose normal through its foot passes through the axis,
// all chords one distance from it, the feet's angles a helix half a step ahead of the nosings. The
// axis and that distance are fitted to the chords; the nosings are put half a step behind, from an
// assumed column (rim_column_radius_m) to the rim.

#include <vector>

#include "core/LineSegment.h"

namespace stairmap {

struct SpiralSearchParams {
    double floor_z = 0.0;                  ///< [m] floor the robot stands on
    double min_first_height_m = 0.05;      ///< [m] lowest allowed nosing above the floor
    double max_first_height_m = 1.05;      ///< [m] the lowest found nosing must be below this ...
    /// [-] ... unless the helix holds this many seen levels and its lowest one lies a whole number
    /// of rises (within height_tolerance_m) above the floor: an elevation map keeps only the top
    /// surface, so where a spiral turns more than once its upper wedges hide the lower ones and
    /// only levels 1.2 m and more above the floor are seen (dev5 r0683, dev6 r0671: 6 levels).
    /// The levels below are put back on the helix down to the floor. Few-level helices must
    /// start low.
    int high_start_min_seen_levels = 6;
    int high_start_max_levels_below = 8;   ///< [-] at most this many levels put back below
    double min_rise_m = 0.11;              ///< [m] rise range (DetectorParams condition 1)
    double max_rise_m = 0.30;              ///< [m]
    /// [m] a helix's rise may read this much below min_rise_m (rises of 0.10-0.11 m read
    /// 0.093-0.107 m; the straight flights' kFlightRiseNoise) ...
    double low_rise_noise_m = 0.02;
    /// [-] ... when at most this many of its levels are put back: a finer helix through a
    /// spiral's nosings indexes more levels than the true one only by putting unseen ones back
    /// between them (dev r0047: 2 of 8, dev2 r0066: 4 of 15, each a true rise of 0.104 / 0.126 m
    /// read as 0.103 m), where the low-rise spirals found by it put back 0 or 1
    int max_put_back_below_min_rise = 1;
    double min_run_m = 0.15;               ///< [m] run at mid radius (condition 2)
    double max_run_m = 0.45;               ///< [m]
    double min_step_angle_deg = 10.0;      ///< [deg] turn per step: below this the flight is straight
    double max_step_angle_deg = 70.0;      ///< [deg]
    double max_column_radius_m = 0.45;     ///< [m] inner end of a nosing at most this far from the axis
    double min_outer_radius_m = 0.40;      ///< [m] outer end at least this far (wedges of a stair)
    double max_axis_offset_m = 0.08;       ///< [m] a nosing's line passes this close to the axis
    double angle_tolerance_deg = 9.0;      ///< [deg] angle around the axis off the helix
    double height_tolerance_m = 0.035;     ///< [m] level off the fitted rise
    int max_missing_levels = 2;            ///< [-] unseen levels put back between two seen ones
    /// [steps] a gap of unseen levels must turn as many step angles as it rises, within this: a
    /// helix through nosings below and back edges above turns one step more across its gap
    /// (0.25 and 0.5 kept the same flights on the development sets)
    double gap_turn_tolerance_steps = 0.35;
    int min_steps = 4;                     ///< [-] fewest levels of a spiral (seen + put back)
    /// [-] fewest seen levels: 4 reported extra flights on the mapping test's accumulated submaps
    /// (tests/pipeline/TwoFloorDrive); 5 keeps dev recall and lowers spiral rise MAE
    int min_seen_levels = 5;
    int max_spirals = 2;                   ///< [-] search repeats on the remaining lines
    /// [-] when > 0, an axis is looked for only through pairs that hold one of the first this many
    /// lines of front_drops (lines of another kind added to a search already made on the rest:
    /// StairDetector's tread nosings); every line may still be an inlier. 0 = every pair.
    int pair_lines = 0;
    /// [-] findSpirals' `few_level`: the best helix of this many seen levels (fewer than
    /// min_seen_levels) among the lines no spiral took, everything else asked as of a spiral.
    /// 0 = none.
    int few_seen_levels = 0;
    /// [-] unseen levels such a helix may have put back between its seen ones: with four seen
    /// levels the rise rests on them alone, and helices with gaps read rises and runs far off
    /// (check11 r0069: 10 cm, check12 r0117: 12 cm of run, with 2); with 0 they read like the
    /// others
    int few_max_missing_levels = 0;
    /// Extra levels, admitted once a helix holds this many levels of lines found under the bounds
    /// above [-]: where a close view's column hides a nosing's inner part, or a back edge's line
    /// passes a little farther from the fitted axis, a level sits exactly on the helix's angle and
    /// height yet fails them. Such lines only fill levels left empty and never move the axis.
    int min_strict_levels = 3;
    double extra_max_axis_offset_m = 0.12;  ///< [m] an extra level's line passes this close to the axis
    double extra_max_inner_share = 0.8;     ///< [-] its inner end at most this share of the outer radius
    /// [m] its outer end this close to the held levels' farthest one (it reaches the outer rim)
    double extra_outer_tolerance_m = 0.10;
    /// [m] the held levels' inner ends lie within this of each other (they stop at one column):
    /// without it, radial-looking lines of straight flights on an accumulated submap
    /// (tests/pipeline/TwoFloorDrive) were filled up to a spiral
    double extra_max_inner_spread_m = 0.15;
    /// Spirals seen by their treads' outer rims (an elevation map cropped at the spiral): chords
    /// whose normals pass through the axis, all one distance from it.
    bool rim_search = true;
    double max_rim_distance_m = 2.0;       ///< [m] farthest rim chord from the axis
    double rim_distance_tolerance_m = 0.05; ///< [m] a chord's distance off the common one
    double rim_chord_tolerance_m = 0.10;   ///< [m] a line may reach this far past its chord's ends
    /// [deg] a rim's foot off the helix: a partly seen arc's line has its foot at the seen part's
    /// middle, anywhere within the tread's step angle (9 deg missed dev r0189, 15 deg raised dev2
    /// width MAE with no gain)
    double rim_angle_tolerance_deg = 12.0;
    /// [m] column radius assumed for the nosings of a spiral seen only by its rims (unseen; dev
    /// and dev2 columns are 0.06-0.30 m)
    double rim_column_radius_m = 0.15;
};

/// A found spiral: its nosings from the lowest up (z real, put-back levels have num_points 0).
struct SpiralFlight {
    std::vector<LineSegment> edges;
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();  ///< [m] XY of the column's axis
    double outer_radius_m = 0.0;                     ///< [m] median outer end distance to the axis
    double inner_radius_m = 0.0;                     ///< [m] nearest inner end to the axis (column)
    double step_angle_rad = 0.0;                     ///< [rad] turn per step (> 0)
    /// [m] chord between consecutive nosings' centres (mid radius): the run of a turning flight,
    /// independent of how much of each nosing was seen
    double run_m = 0.0;
    int seen_levels = 0;                             ///< levels with a line of their own
};

/// Where no spiral was found: the axis whose helix held the most seen levels (findSpirals'
/// `glimpse`). A spiral whose nosings are seen too poorly for a spiral often shows its axis through
/// three of them (StairDetector then looks at its treads there).
struct SpiralGlimpse {
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();  ///< [m] XY
    int seen_levels = 0;                             ///< 0 = none
};

/// Spirals among the lines of both drop directions (real z, any order; `front_drops` lower towards
/// the robot at the origin, `back_drops` lower away from it). Ascending flights only. With
/// `few_level` given and params.few_seen_levels set, the best spiral of that many seen levels
/// among the lines left once the search ends (at most one) goes there. With `glimpse` given, the
/// helix of most seen levels (three inlier lines at least) among those that made no spiral goes
/// there.
std::vector<SpiralFlight> findSpirals(const std::vector<LineSegment>& front_drops,
                                      const std::vector<LineSegment>& back_drops,
                                      const SpiralSearchParams& params,
                                      std::vector<SpiralFlight>* few_level = nullptr,
                                      SpiralGlimpse* glimpse = nullptr);

}  // namespace stairmap
