#pragma once
// A short chain that is the foot of a longer flight (issue 10, whole flights). Algorithm 1 needs
// min_steps edges (4): a chain of three is what a two-step stage gives (two steps and its
// platform's edge), so it is refused. But a far or oblique view often finds the lines of only three
// nosings of a long flight while the tread one step above the last of them is in the cloud (dev:
// 22 misses end as a refused chain of 2-3 edges on the flight's nosings). A stage's platform is flat behind its edge; a flight's
// next tread lies one rise higher and one run further. Where the cloud shows that tread, the
// chain gets its next nosing back (unseen: no line of its own) and counts.

#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap {

struct FlightContinuationParams {
    double tread_dz_m = 0.03;     ///< [m] a point is on a tread within this of its height
    /// [-] the next tread's window behind the last edge, in runs: one run further (the next
    /// nosing) plus the middle of the tread (away from both risers)
    double from_runs = 1.2;
    double to_runs = 1.8;
    double end_fraction = 0.15;   ///< [0..1] of the edge's length left out at each end (walls)
    /// [0..1] the next tread's points must spread over at least this fraction of the edge's length
    double min_spread_fraction = 0.2;
    int min_points = 4;           ///< [-] fewest points on the next tread
    /// [m] points this far above the next tread in its window are a wall or a box, not a tread
    double above_dz_m = 0.08;
    /// [-] the chain itself must be a regular straight flight: every pair's rise and run within
    /// this fraction of the chain's mean ...
    double max_step_deviation = 0.2;
    double max_turn_deg = 8.0;    ///< [deg] ... and its edges this parallel to the last one
    double min_rise_m = 0.11;     ///< [m] mean rise at least this (DetectorParams condition 1) ...
    /// [m] ... less this: the noise of a mean of two measured rises (flights of 0.10-0.11 m rises
    /// read 0.096-0.107 m: dev r0074, dev2 r0078)
    double mean_rise_noise_m = 0.015;
    /// [m] a landing a flight starts from lies at least this above the robot's floor: one low
    /// step (condition 1's 0.11 m) less the tread tolerance; the real ANYmal entrance's landing is
    /// 0.10 m above the level in front of it
    double min_landing_height_m = 0.08;
    /// A line two steps beyond the last edge (lineTwoStepsBeyond): this many runs behind it ...
    double beyond_from_runs = 1.8;
    double beyond_to_runs = 2.2;
    /// [-] ... this many chain rises above it (a far level LiDAR's riser hits read up to a rise
    /// low, so the line two nosings up reads 1-2 rises above a last edge itself read low or not)
    double beyond_min_rises = 0.9;
    double beyond_max_rises = 2.5;
    /// [0..1] ... overlapping the last edge over this fraction of the shorter one
    double beyond_min_overlap = 0.5;
    /// A ramp's chain (treadsRiseAlongTheRun): the points between its first and last edge lie
    /// closer (RMS) to one sloped line than this fraction of their distance to the stair's
    /// profile (treads at their edges' heights, risers under the edges) ... 0.8: check3 r0280's
    /// ramp reads 0.73; of the dev sets' chains tested, those below 0.9 were continued by no cue
    /// anyway, the flights read 1.08 and more
    double ramp_max_rms_ratio = 0.8;
    int ramp_min_points = 20;  ///< [-] ... and are at least this many
    /// [-] ... of every this-many-th point of the cloud (1: all; a whole flight's test samples)
    int ramp_point_stride = 1;
    /// The next step's riser (riserAboveLastEdge): its window this many runs behind the last
    /// edge (the riser stands one run behind it; range noise and a run read a few cm off) ...
    double riser_from_runs = 0.8;
    double riser_to_runs = 1.3;
    /// [-] ... and this many rises above it: the riser's face, clear of the last tread's
    /// points below and the next tread's above
    double riser_from_rises = 0.25;
    double riser_to_rises = 0.85;
    /// [-] ... and under half as many points at those heights in the next this-many runs behind
    /// the window (the dev sets' flights continued by this cue have none there): a
    /// riser is a face, the tread behind it a rise up; a platform whose edge reads a few cm low
    /// (a riser hit) lies in the window's heights and goes on (two-step stages, negatives of seed
    /// 26026: edges read 3 cm under the platform, which filled the window)
    double riser_beyond_runs = 0.7;
    /// [-] ... and the tread behind the last edge looked at from this many runs behind it up to
    /// the window: seen (min_points; its lower quartile, as debris stands on it) more than
    /// riser_tread_min_raise_rises but less than riser_from_rises rises above the edge, the
    /// window's heights count from it (an edge read low on its riser: a two-step stage's platform
    /// edge read 3 cm under the platform, negatives of seed 26026 r0176, showed one ring on the
    /// platform in the window and none beyond it)
    double riser_tread_from_runs = 0.15;
    double riser_tread_min_raise_rises = 0.1;  ///< [-] of the rise: below it, the edge's noise
};

/// Whether `edges` (an ascending chain from the floor up, real z) are a regular straight flight:
/// every pair's rise and run within max_step_deviation of the chain's means, the mean rise at least
/// min_rise_m - mean_rise_noise_m, every edge within max_turn_deg of the last. No points needed:
/// the cheap test first.
bool isRegularStraightChain(const std::vector<LineSegment>& edges,
                            const FlightContinuationParams& params = {});

/// Whether `edges` (an ascending chain from the floor up, real z, at least 2 edges) are a regular
/// straight flight (isRegularStraightChain) and the cloud shows the tread one step above the last:
/// points at the last edge's height + rise within tread_dz, in the window from_runs..to_runs runs
/// behind it, spread along it, more of them than at the last edge's own height there (a platform),
/// and at most a quarter as many higher up there (a wall, a box). Rise and run are the chain's
/// means. Non-finite points are ignored. Cost: one pass over the cloud.
bool treadAboveLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                        const FlightContinuationParams& params = {});

/// Whether `edges` (as above) are a regular straight flight and the cloud shows the riser of the
/// step above the last edge: points riser_from_rises..riser_to_rises rises above the last edge (or
/// above the tread seen just behind it, when that lies higher: riser_tread_*) in the window
/// riser_from_runs..riser_to_runs runs behind it, spread along it (as the next tread's),
/// more of them than points at the last edge's own height beyond one run (a platform going on),
/// more than twice as many as points at the window's heights up to riser_beyond_runs further
/// behind (a platform whose edge was read low), and at most a quarter as many a rise and above_dz
/// higher (a wall). A level LiDAR lower than a
/// flight's upper treads sees their risers only (dev3 r0071: an HDL-32 6 m away, its first three
/// nosings seen); a two-step stage's platform shows no riser one run behind its edge. Cost: one
/// pass over the cloud.
bool riserAboveLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                        const FlightContinuationParams& params = {});

/// Whether `edges` (as above) are a regular straight flight whose first edge lies two rises above
/// the floor at floor_z, and the cloud shows the tread of the step below it: points one rise below
/// the first edge in the middle of the run in front of it, more of them than at the floor's height.
bool treadBelowFirstEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                         double floor_z, const FlightContinuationParams& params = {});

/// Whether `edges` (as above) are a regular straight flight rising from below the floor at
/// floor_z: its first edge one rise above the floor (within tread_dz_m), so that the nosing one
/// run in front of it lies at the floor's height (never a line: ground rows are not searched),
/// and the cloud shows the tread one rise below the floor in front of that nosing (the window of
/// treadBelowFirstEdge one run further out: a sunken area's floor or the step below), more
/// points there than at the floor's height. A flight from the floor has the floor there.
bool floorNosingAbovePit(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                         double floor_z, const FlightContinuationParams& params = {});

/// Whether `edges` (as above) are a regular straight flight that starts from a landing or platform
/// above the robot's floor: the surface one rise below the first edge, seen in front of it (the
/// window of treadBelowFirstEdge), lies at least min_landing_height_m above floor_z. A two-step
/// stage stands on the floor; three rises from a raised landing are the upper part of a flight
/// split by it (issue 10: the real ANYmal entrance, one step up onto a landing, then the flight).
bool startsFromRaisedLanding(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                             double floor_z, const FlightContinuationParams& params = {});

/// Whether `edges` (as above) are a regular straight flight and nothing at all was seen at or
/// above the last edge's height one step beyond it (the window of treadAboveLastEdge): the flight
/// may go on where the view does not reach, while a stage's platform would be seen there.
bool unseenBeyondLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                          const FlightContinuationParams& params = {});

/// Whether `edges` (as above, in any z frame: the descending search's mirrored z too) are a
/// regular straight flight and no point at all, at any height, was seen in that window: the view
/// ends there (an elevation map's crop, a shadow), where a pit's floor or the next tread of a
/// descending flight would be seen.
bool nothingBeyondLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           const FlightContinuationParams& params = {});

/// The indices of the lines (of `lines`, real z) two, four, ... steps beyond the last edge of
/// `edges` (as above, at least three edges: a regular straight flight), each two runs behind the
/// one before (beyond_from_runs..beyond_to_runs of the chain's run), higher by
/// beyond_min_rises..beyond_max_rises of its rise, parallel within max_turn_deg and overlapping
/// it; empty when the chain is shorter or not regular, or no line lies two steps beyond its last
/// edge. A far level LiDAR's rings alias with the steps: it sees three nosings of a long flight
/// and then every other one (dev2 r0133, a VLP-16 at 6 m), whose lines Algorithm 1 cannot join:
/// their heights, read on the risers, are off the two rises it asks for by up to a rise. A
/// two-step stage shows no edge two steps behind its platform's.
std::vector<int> linesEveryOtherStepBeyond(const std::vector<LineSegment>& lines,
                                           const std::vector<LineSegment>& edges,
                                           const FlightContinuationParams& params = {});

/// Whether the points between the first and the last edge of `edges` (as above, real z) lie on
/// one sloped surface: closer (RMS) to one line of height against the distance up the chain than
/// ramp_max_rms_ratio times their distance to the stair profile the edges make (treads at their
/// edges' heights, risers under the edges). The rings of a LiDAR crossing a ramp give edge lines
/// a "rise" apart, and the ramp beyond the last one reads as the next tread (check3 r0280, a 14
/// deg ramp seen by a pitched OS1-64). Cost: one pass over the cloud (a box test per point).
bool treadsRiseAlongTheRun(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           const FlightContinuationParams& params = {});

/// The nosing one rise above and one run behind the last edge (unseen, num_points 0), as wide as it.
LineSegment nextNosing(const std::vector<LineSegment>& edges);
/// The nosing one rise below and one run in front of the first edge (unseen), as wide as it.
LineSegment previousNosing(const std::vector<LineSegment>& edges);

}  // namespace stairmap
