#pragma once
// All thresholds of the staircase detector (paper Sec. III), with the paper's defaults where it gives
// them. Field names match the keys of the [detector] section of config/default.ini.
// Frame: gravity-aligned robot frame (x forward, y left, z up); heights are relative to the floor.

#include <cstddef>

#include "core/TopView.h"

namespace stairmap {

/// [bytes] memory budget of the detector's top-view grid (TopView.h). The grid covers the points'
/// XY bounding box cropped to +-max_range_m (points beyond are dropped, never gridded), so its
/// worst case is (2 max_range_m / leaf_size_m + 10)^2 columns of 8 bytes; validate() rejects
/// configurations whose worst case exceeds this. Defaults (10 m, 2.5 cm): 5.2 MB.
constexpr std::size_t kMaxTopViewGridBytes = std::size_t{128} << 20;

struct DetectorParams {
    // --- Pre-processing (Sec. III-A) ---
    double leaf_size_m = 0.025;            ///< [m] voxel / top-view XY cell size (paper Sec. IV-A)
    /// [m] points farther than this in XY are ignored. Bounded with leaf_size_m by the grid budget
    /// kMaxTopViewGridBytes: at most 50.9 m at 2.5 cm, 20.3 m at 1 cm, 10.1 m at 5 mm.
    double max_range_m = 10.0;
    double max_height_above_floor_m = 3.0; ///< [m] points higher above the floor are ignored
    double max_depth_below_floor_m = 3.0;  ///< [m] points lower below the floor are ignored
    double row_height_m = 0.025;           ///< [m] z bin of the cylindrical organisation
    /// [m] rows of the tilted-ring pass. A LiDAR pitched down sees a flight off its pitch axis
    /// with rings that cross each riser at a slant (at 28 deg pitch and 30 deg off the axis, some
    /// 30 cm of height over a 1.4 m riser at 6 m), so a riser's hits spread over several rows,
    /// each piece too short for a line: a flight seen so gives few lines or none. A pass with
    /// rows this tall, the last one, on the lines off the flights the others found, adds the
    /// flights it finds there. Must exceed row_height_m; 0 = off.
    double tilted_ring_row_height_m = 0.05;
    int azimuth_bins = 1800;               ///< [-] azimuth columns over 360 deg (0.2 deg each)
    /// [m] a top-view cell is an edge candidate when its neighbour towards the robot is lower or
    /// higher by more than this (or empty). Below the minimum rise, above 2x the point noise.
    double edge_min_dz_m = 0.05;
    /// [m] ...but not when the neighbour on the other side is higher than this: that column is the
    /// top of a riser just below the real nosing (points spilled there by noise).
    double edge_spill_dz_m = 0.025;
    /// [m] how far along the ray the top view looks for a column's neighbour; nothing within it
    /// counts as a drop (a shadow, an edge). Longer than the holes of the coarsest cloud: 20 cm,
    /// the gap that also cuts a row into lines; 7.5 cm took the holes of elevation maps' 4 cm
    /// cells and far rings for drops, whose stray lines broke real flights (dev set: elevation
    /// maps 59 -> 68 of 75 flights). At most 8 columns. The mapping presets keep 0.075: their
    /// accumulated submaps have no such holes, and tests of their landmarks were validated so.
    double neighbour_walk_m = 0.20;

    // --- Segmentation (Sec. III-B) ---
    double split_distance_m = 0.03;   ///< [m] d_p of the iterative end-point fit
    /// [-] noisy clouds: d_p is raised to this many times the floor's measured height noise
    /// (FloorNoise.h), up to max_split_distance_m. A depth camera's range noise grows with the
    /// range squared (4-8 cm at 3-4 m): its nosings' columns scatter by more than 3 cm and break
    /// into pieces too short to be lines. With 4 the noisiest LiDAR of the dev sets gets 3.3 cm
    /// (floor noise <= 0.82 cm), depth cameras 3-5 cm (0.67-3.2 cm). 0 = the paper's fixed d_p; the
    /// mapping presets use 0 (their submaps are accumulated, voxelised clouds, not one noisy view).
    double split_noise_factor = 4.0;
    /// [m] highest d_p a noisy cloud gets (6 cm gave 1 more flight on dev but run MAE 0.54 ->
    /// 0.56 cm and 0.57 -> 0.60 cm on dev2: wider splits fuse noise across the nosings)
    double max_split_distance_m = 0.05;
    int min_line_points = 5;          ///< [-] N_min, fewest points of a line
    double min_line_length_m = 0.20;  ///< [m] shorter lines are dropped (debris, clutter)
    double max_point_gap_m = 0.20;    ///< [m] a row is cut where neighbours are farther apart
    /// [m] the dashed-nosing pass: Algorithm 1 once more (rows of row_height_m, then of
    /// tilted_ring_row_height_m), on the lines off the flights found, with rows cut only at gaps
    /// longer than this. A pitched or far LiDAR's rings cross a nosing in dashes of a few columns
    /// 0.3-0.5 m apart (dev r0126, an HDL-32 pitched 24 deg 6-10 m away: four cells every 0.45
    /// m), each too short for a line at max_point_gap_m. Its flights need min_steps edges, regular
    /// rises and runs, and must be no ramp at the short chains' bound (StairDetector.cpp,
    /// addDashedNosingFlights); the spiral search is not asked. 0 = off; else above
    /// max_point_gap_m.
    double dashed_nosing_gap_m = 0.5;
    /// [-] the sparse-line pass: Algorithm 1 once more, on the lines off the flights found, with
    /// lines of this many points (fewer than min_line_points). Far LiDARs' rings and depth
    /// cameras' noisy rows leave nosings with a line of four top-view columns where the first
    /// pass needs five (dev r0114, a level VLP-16 7.9 m from an open-riser flight; dev3 r0090, a
    /// spiral 0.7 m in front of a VLP-16 pitched down 16 deg). Its flights need min_steps edges,
    /// condition 1's rise and must be no ramp at the short chains' bound; unlike the dashed pass's
    /// they may turn (spirals chained step by step). The spiral search is not asked. 0 = off;
    /// else 2 .. min_line_points - 1.
    int sparse_line_points = 4;
    /// [-] spirals seen over this many levels, fewer than the spiral search's five (SpiralSearch
    /// min_seen_levels), are looked for too on the first pass's lines and added after every pass
    /// where no flight found lies on them: a near view of a short spiral shows four levels with
    /// lines (dev3 r0003); every level must be seen (SpiralSearchParams::few_max_missing_levels).
    /// Asked in the search itself, four-level helices displaced the longer flights later passes
    /// find on the same spiral (dev2 r0005, r0091) and read rises and runs worse (dev rise MAE
    /// 0.244 -> 0.279 cm). 0 = off; else 2 .. 4.
    int few_level_spiral_levels = 4;
    /// [m] spirals read from their treads (TreadBoundaries): where the spiral search found no
    /// spiral but glimpsed an axis through three seen levels, a coarse top surface of this cell
    /// size is made about it, nosings are read as the boundaries between its flat patches one rise
    /// apart, and the search runs once more on them with the first pass's lines, four seen levels
    /// enough; a spiral it finds is added after every pass where no flight found lies on it (as
    /// few_level_spiral_levels). A depth camera over a spiral's foot shows the wedge treads well
    /// but its row lines miss the nosings seen along the line of sight (dev6 r0718). 0 = off; else
    /// 0.02 .. 0.2.
    double tread_spiral_cell_m = 0.05;
    /// [m] half size of that surface about the glimpsed axis (a spiral's outer radius is at most
    /// 0.3 + 2.5 m on the benchmark, most are below 1.5 m)
    double tread_spiral_window_m = 3.0;
    double point_sigma_m = 0.01;      ///< [m] std. dev. of a point for the weighted line fit
    double merge_chi2 = 9.21;         ///< [-] Mahalanobis gate to merge lines (chi2, 2 dof, 99 %)
    double vertical_merge_dz_m = 0.06;    ///< [m] lines of nearby rows closer in z are fused ...
    double vertical_merge_dist_m = 0.04;  ///< [m] ... when also this close in XY
    /// [m] collinear pieces of one edge (e.g. interrupted by debris) are fused across this gap
    double max_collinear_gap_m = 0.40;

    // --- Grouping (Sec. III-B, last paragraph) ---
    double floor_tolerance_m = 0.05;      ///< [m] lines within this of the floor are ground lines
    double floor_refine_window_m = 0.10;  ///< [m] a given floor height is refined within +- this
    double floor_search_radius_m = 3.0;   ///< [m] XY radius used to estimate / refine the floor

    // --- Definition 1 (stair constraints, OSHA) ---
    double min_step_height_m = 0.11;  ///< [m] condition 1, minimum rise
    double max_step_height_m = 0.30;  ///< [m] condition 1, maximum rise
    double min_step_depth_m = 0.15;   ///< [m] condition 2, minimum run
    double max_step_depth_m = 0.45;   ///< [m] condition 2, maximum run
    /// [deg] condition 3, minimum slope atan(h/d). The paper uses 25; shallow entrance flights
    /// (0.11 m rises on 0.30 m runs: 20 deg) are real stairs, so 20 is the default. Lower is not
    /// safe: a LiDAR's rings on a steep ramp are evenly spaced level lines whose slope is the
    /// ramp's (datasets/clouds/ramp_steep_0 becomes two staircases at 12 deg).
    double min_slope_deg = 20.0;
    double max_slope_deg = 60.0;      ///< [deg] condition 3, maximum slope
    /// [m] deep treads (LongTreads.h): an ascending chain with runs beyond max_step_depth_m up to
    /// this counts where the cloud shows every one of its treads level (outdoor and entrance
    /// flights; the real ANYmal entrance reads 0.44-0.64 m). 0 = off.
    double max_level_tread_depth_m = 0.65;
    /// [m] a chain of three edges whose treads are seen level and at least this deep on average
    /// also counts when nothing is seen one step beyond its last edge (indoor flights' treads are
    /// 0.22-0.32 m; a stage's platform would be seen there). Must lie in [min_step_depth_m,
    /// max_level_tread_depth_m].
    double min_deep_tread_m = 0.40;
    /// [deg] condition 3's minimum slope for such chains (0.19 m rises on 0.64 m treads: 16.5 deg)
    double min_level_tread_slope_deg = 15.0;
    /// Ring-aliased flights seen in part: a chain of three edges (one short of min_steps) that no
    /// cue above continues counts when lines lie every other step beyond its last edge
    /// (FlightContinuation.h, linesEveryOtherStepBeyond); they join it with the nosings between
    /// put back. A far level LiDAR sees three nosings and then every other one (dev2 r0133).
    bool continue_every_other_step = true;
    /// A chain one edge short of min_steps is also continued where the cloud shows the next
    /// step's riser one run beyond its last edge (FlightContinuation.h, riserAboveLastEdge): a
    /// level LiDAR below the flight's upper treads sees their risers, not their treads (dev3
    /// r0071, an HDL-32 6 m away). A stage's platform shows no riser there.
    bool continue_by_next_riser = true;
    /// Ascending flights whose foot lies below the robot's floor (a sunken area or a pit in front
    /// of the flight, issue 10: flights 1-3 steps below missed 28 % on the dev sets, against 8 %
    /// from the floor). Their nosing at the floor's height is never a line (ground rows are not
    /// searched), so a last pass of Algorithm 1, where no flight was found, counts that nosing
    /// when a chain steps over it, starts from lines below the floor when the chains from the
    /// floor fall short (the chain must rise above the floor), and gives a chain one edge short
    /// whose first edge is one rise up that nosing when the tread a rise below the floor is seen in
    /// front of it (FlightContinuation.h, floorNosingAbovePit). Run last, on the lines off the
    /// flights the other passes found: their readings of a flight are kept.
    bool ascend_from_below_floor = true;
    /// Straight ascending flights read from their profile (ProfileChains.h): where no chain of
    /// Algorithm 1 joins a flight's lines (pieces at their own places along each nosing, every
    /// other nosing seen: a far level LiDAR), a last pass looks, among parallel lines off the
    /// flights found, for a comb of heights and distances up the flight, a whole number of rises
    /// above the floor, holding five steps or more.
    bool profile_flights = true;
    /// An ascending chain whose lines stand one to three runs apart while its heights, read from
    /// riser hits above the sensor, put them on other levels (a far LiDAR's rings' spacing) is
    /// levelled by its lines' spacing, the nosings stepped over put back (MissingNosings.h,
    /// fillNosingsBySpacing; dev3 r0288, a level VLP-16 7.4 m away); off: by its heights only.
    bool level_by_line_spacing = true;
    /// [-] an ascending straight flight whose points between its first and last edge lie closer
    /// (RMS) to one sloped line than this fraction of their distance to its stair profile is a
    /// ramp's ring lines and dropped (FlightContinuation.h, treadsRiseAlongTheRun); 0 = off. The
    /// short chains' continuation asks 0.8 (ramp_max_rms_ratio); whole flights read 0.75 and
    /// more on the dev sets, the ramp of check4 r0150 0.15-0.46.
    double max_ramp_rms_ratio = 0.6;
    /// [0..1] a descending flight whose first edge lies below the floor starts from level
    /// surfaces (a tread, a landing, the steps above it); when more than this fraction of the
    /// points in front of that edge lie off those levels, it starts on a ramp and is a ramp's ring
    /// lines seen from its top (DescentStart.h). Found descents on the dev sets read 0-0.04, the
    /// dev negatives' ramps 0.36-0.73. 1 = off.
    double max_descent_start_off_level = 0.2;
    /// [m] ring-aliased flights: a far LiDAR may see every other nosing only (each pair two
    /// steps apart, runs beyond condition 2's bound). An ascending chain of such pairs, its rises
    /// in [2 min_step_height_m, this] and runs in [2 min_step_depth_m, 2 max_step_depth_m], whose
    /// treads are not seen level (a real deep tread is flat, an aliased pair's holds a riser) and
    /// with no line where a skipped nosing would lie (a dense noisy view's chain that merely
    /// stepped over lines) and off the flights found, is the flight with every other nosing put
    /// back halfway. 0.26 (0.30 with the sparse-mode tolerance) keeps bleachers' 0.36-0.50 m tiers
    /// out. 0 = off.
    double max_double_step_rise_m = 0.26;
    /// [deg] condition 4, consecutive edges parallel within this. The paper uses 10; a spiral's
    /// wedge treads turn run / mid radius per step: 15-25 deg on wide spirals, up to 40 deg and more
    /// on narrow ones (0.3 m run at 0.45 m mid radius: 38 deg), so 45 is the default (rise, run,
    /// slope and "no line in between" still reject the negatives).
    double max_parallel_deg = 45.0;
    /// [m] sparse-cloud mode. Above its own height a LiDAR sees no tread, only the riser below
    /// each nosing, and the highest hit there reads up to one beam spacing low (2 deg: 7 cm at
    /// 2 m). With a tolerance > 0, conditions 1 and 3 accept a pair whose rise is off by up to this
    /// much, lines lying under a higher line are dropped as riser hits (RiserHits.h), and a
    /// flight's edges far below its fitted nosing line are raised onto it. 0 = the paper's strict
    /// tests. Single clouds (`stairmap detect`, config/default.ini) use 0.04; the mapping presets
    /// use 0: their accumulated submaps see the nosings from many poses, and there the tolerance
    /// admitted riser hits that biased the fused rise by 0.4 cm on the two-floor run.
    double edge_height_tolerance_m = 0.04;
    /// [-] condition 5: a line between two edges blocks them when it covers at least this fraction
    /// of their common extent (short debris does not block, a ramp's full-width lines do).
    double between_overlap_ratio = 0.5;
    /// [-] two consecutive edges must overlap laterally by this fraction of the shorter one
    double min_overlap_ratio = 0.3;

    // --- Algorithm 1 ---
    /// [-] initialisation list: lines within this x max rise of the floor. 3.5 (not 2.5) lets a
    /// flight whose first two or three nosings are hidden (debris, occlusion) still start.
    double init_height_factor = 3.5;
    /// [-] fewest edges (nosings) of a staircase. The paper asks for more than 4 lines; 4 keeps a
    /// short real flight of 3 steps (3 treads' nosings + the landing's) while a 1-2 step stage
    /// (at most 3 nosings with its platform edge) and curbs are rejected.
    int min_steps = 4;
    int max_staircases_per_direction = 4;  ///< [-] search repeats on the remaining lines
    bool detect_ascending = true;          ///< search above-ground lines
    bool detect_descending = true;         ///< search below-ground lines

    /// Throws std::invalid_argument naming the first field that is out of range, or max_range_m
    /// (with leaf_size_m) when the top-view grid could exceed kMaxTopViewGridBytes.
    void validate() const;

    /// [bytes] the top-view grid for points spread over the whole configured range (worst case).
    double topViewGridBytes() const;
};

/// The top view's parameters (TopView.h) for a floor at `floor_z` [m]: its height band, the edge
/// thresholds, and the ground band (floor +- floor_tolerance_m) where only descending nosings are
/// looked for.
TopViewParams topViewParams(const DetectorParams& params, double floor_z);

}  // namespace stairmap
