#include "core/StairDetector.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/CylindricalRows.h"
#include "core/DescentEnd.h"
#include "core/DescentStart.h"
#include "core/FlightContinuation.h"
#include "core/FlightFootprint.h"
#include "core/FlightJoin.h"
#include "core/FlightPoints.h"
#include "core/FloorEstimation.h"
#include "core/FloorNoise.h"
#include "core/FloorNosing.h"
#include "core/LineFusion.h"
#include "core/LongTreads.h"
#include "core/MissingNosings.h"
#include "core/NosingSlope.h"
#include "core/OverlappingFlights.h"
#include "core/ProfileChains.h"
#include "core/RayClearance.h"
#include "core/ReverseReadings.h"
#include "core/RiserHits.h"
#include "core/RowLinesCache.h"
#include "core/RowSegmentation.h"
#include "core/SpiralColumn.h"
#include "core/SpiralPieces.h"
#include "core/SpiralSearch.h"
#include "core/StairPairExplain.h"
#include "core/StairSearch.h"
#include "core/StaircaseGeometry.h"
#include "core/StartSurface.h"
#include "core/StepExtent.h"
#include "core/TallRisers.h"
#include "core/TopView.h"
#include "core/TreadHeights.h"
#include "core/TreadSpirals.h"
#include "core/TurningFlight.h"

namespace stairmap {
namespace {

/// [m] an edge this far below its flight's fitted nosing line is a riser hit
constexpr double kRiserHitMinDrop = 0.02;
/// [1/m^2] treads seen this densely (one point per 5 cm cell: elevation maps, near depth cameras)
/// make an empty patch beyond a flight mean that nothing is there (LevelTreadParams)
constexpr double kDenseTreadPointsPerM2 = 400.0;

/// Floor height: the given one refined to the dominant level within +-window, or estimated.
std::pair<double, bool> resolveFloor(const PointCloud& cloud, std::optional<double> floor_z,
                                     const DetectorParams& p) {
    FloorSearch s;
    s.radius_m = p.floor_search_radius_m;
    if (floor_z) {
        s.z_lo = *floor_z - p.floor_refine_window_m;
        s.z_hi = *floor_z + p.floor_refine_window_m;
        return {dominantLevel(cloud, s).value_or(*floor_z), false};
    }
    s.z_lo = -p.max_depth_below_floor_m - 2.0;
    s.z_hi = 0.3;  // the robot frame origin is on or above the floor it stands on
    const auto level = dominantLevel(cloud, s);
    return {level.value_or(-0.5), true};
}

/// `p` with the split distance d_p raised for a noisy cloud (DetectorParams::split_noise_factor).
DetectorParams withNoisySplitDistance(const DetectorParams& p, const PointCloud& cloud,
                                      double floor_z, DetectorDebug* debug) {
    DetectorParams out = p;
    if (p.split_noise_factor > 0) {
        const double noise = floorHeightNoise(cloud, floor_z);
        out.split_distance_m = std::clamp(p.split_noise_factor * noise, p.split_distance_m,
                                          std::max(p.split_distance_m, p.max_split_distance_m));
        if (debug) debug->floor_noise_m = noise;
    }
    if (debug) debug->split_distance_m = out.split_distance_m;
    return out;
}

SegmentationParams segmentationParams(const DetectorParams& p) {
    SegmentationParams s;
    s.split_distance_m = p.split_distance_m;
    s.min_line_points = p.min_line_points;
    s.min_line_length_m = p.min_line_length_m;
    s.max_point_gap_m = p.max_point_gap_m;
    s.point_sigma_m = p.point_sigma_m;
    s.merge_chi2 = p.merge_chi2;
    return s;
}

/// The top view's nosing candidates, and the cylindrical arrays built from them so far.
struct Candidates {
    const std::vector<TopViewCell>& cells;
    CylindricalRowsCache& arrays;
    RowLinesCache& lines;  ///< segmentations of `arrays`, shared by the passes
};

/// Lines of one kind of nosing (front drops for ascending, back drops for descending).
std::vector<LineSegment> extractLines(const Candidates& cand, std::uint8_t flag, double floor_z,
                                      const DetectorParams& p) {
    CylindricalParams cp;
    cp.z_lo = floor_z - p.max_depth_below_floor_m;
    cp.z_hi = floor_z + p.max_height_above_floor_m;
    cp.row_height_m = p.row_height_m;
    cp.azimuth_bins = p.azimuth_bins;
    cp.skip_z_lo = floor_z - p.floor_tolerance_m;  // ground lines are not used by the search
    cp.skip_z_hi = floor_z + p.floor_tolerance_m;
    const CylindricalRows& rows = cand.arrays.rows(cand.cells, flag, cp);
    std::vector<LineSegment> lines;
    // Segmented once for the sparse-line pass's fewer points, which asks for the same rows.
    const int fewest_points = p.sparse_line_points > 0 ? p.sparse_line_points : p.min_line_points;
    cand.lines.lines(rows, segmentationParams(p), fewest_points, lines);
    LineFusionParams fp;
    fp.max_dz_m = p.vertical_merge_dz_m;
    fp.max_distance_m = p.vertical_merge_dist_m;
    fp.max_gap_m = p.max_collinear_gap_m;
    fuseDuplicateLines(lines, fp);
    if (p.edge_height_tolerance_m > 0) {  // sparse-cloud mode, see DetectorParams
        RiserHitParams rp;
        rp.max_dz_m = p.max_step_height_m;
        dropRiserHits(lines, rp);
    }
    return lines;
}

/// Builds a Staircase from its edges (z already real), oriented left -> right along the heading.
/// Each edge is lengthened by `end_margin` at both ends: its end points are points of the end
/// columns, on average half a column inside the real end of the edge.
Staircase makeStaircase(const std::vector<LineSegment>& edges, StairDirection dir,
                        double end_margin) {
    Staircase s;
    s.direction = dir;
    const Eigen::Vector2d heading = (edges.back().centre() - edges.front().centre()).normalized();
    const Eigen::Vector2d left(-heading.y(), heading.x());
    for (const LineSegment& l : edges) {
        StairEdge e;
        const bool start_is_left = left.dot(l.start - l.end) >= 0;
        const Eigen::Vector2d a = start_is_left ? l.start : l.end;
        const Eigen::Vector2d b = start_is_left ? l.end : l.start;
        const Eigen::Vector2d u = (b - a).normalized();
        e.start << a - end_margin * u, l.z;
        e.end << b + end_margin * u, l.z;
        e.cov_rho_theta = l.cov;
        e.num_points = l.num_points;
        s.steps.push_back(e);
    }
    s.heading_rad = std::atan2(heading.y(), heading.x());
    estimateGeometry(s);
    return s;
}

/// Descending: prepends the floor's own edge (steps[0] by convention), measured one run before the
/// first lower nosing when that one is a valid rise below the floor.
void prependFloorNosing(const std::vector<TopViewCell>& cells, double floor_z,
                        const DetectorParams& p, std::vector<LineSegment>& edges) {
    const double drop = floor_z - edges.front().z;
    if (drop < p.min_step_height_m || drop > p.max_step_height_m) return;
    Staircase probe = makeStaircase(edges, StairDirection::Descending, 0.0);
    FloorNosingParams fp;
    fp.floor_z = floor_z;
    fp.z_tolerance_m = p.floor_tolerance_m;
    const Eigen::Vector2d heading(std::cos(probe.heading_rad), std::sin(probe.heading_rad));
    const auto nosing = measureFloorNosing(cells, edges.front(), heading, probe.step_depth, fp);
    if (nosing) edges.insert(edges.begin(), *nosing);
}

/// [m] noise of a flight's rise measured over all its steps, after the sparse-mode corrections
constexpr double kFlightRiseNoise = 0.02;

/// Debug record of one direction: its lines (real z) and the chains the search refused.
void recordDirection(const std::vector<LineSegment>& lines, const std::vector<char>& used,
                     const std::vector<int>& refused, StairDirection dir, double floor_z,
                     const DetectorParams& p, DetectorDebug& debug) {
    const bool up = dir == StairDirection::Ascending;
    auto& out = up ? debug.lines_ascending : debug.lines_descending;
    for (LineSegment l : lines) {
        if (!up) l.z = 2 * floor_z - l.z;
        out.push_back(l);
    }
    if (!refused.empty() && debug.rejected.size() < DetectorDebug::kMaxRejected) {
        RejectedChain chain{dir, {}, tooFewSteps(refused.size(), up ? p.min_steps : p.min_steps - 1)};
        for (int idx : refused) chain.edges.push_back(lines[idx]);
        if (!up) for (auto& e : chain.edges) e.z = 2 * floor_z - e.z;
        debug.rejected.push_back(std::move(chain));
    }
    explainRefusedPairs(lines, used, dir, floor_z, p, debug.rejected);
}

/// A box around `edges` holding the boxes that raiseEdgesToTreads and edgeClearances (default
/// parameters) select their points with: either selects from the points of `cloud` in it exactly
/// what it would select from the whole cloud. Edges keep their XY, and raiseEdgesToTreads lifts
/// each by less than a rise, so the second box is known before the first step runs.
FlightBox bothCorrectionsBox(const std::vector<LineSegment>& edges, double rise, double run) {
    const TreadHeightParams tp;
    const RayClearanceParams rp;
    constexpr double kSlack = 0.01;  // [m] beyond both boxes: no rounding decides a point
    double z_lo = edges.front().z, z_hi = z_lo;
    for (const LineSegment& e : edges) {
        z_lo = std::min(z_lo, e.z);
        z_hi = std::max(z_hi, e.z);
    }
    const double margin = std::max(run, rp.max_behind_runs * run + rp.min_behind_m) + kSlack;
    const double below = std::max(tp.below_m, rp.under_slack_m) + kSlack;
    const double above = std::max(tp.max_raise_fraction, rp.max_behind_runs + 3.0) * rise + kSlack;
    return flightBox(edges, margin, z_lo - below, z_hi + above);
}

/// Whether more than a third of `cloud` lies in `box`, judged from every 16th point. A sparse
/// cloud seen from afar has a small part of it near a flight: a copy of that part spares both
/// corrections a pass over the rest. A dense depth camera looking down at the flight has most of
/// its view there: the copy then costs more than it spares (counting passes, break-even lies
/// near a third).
bool mostlyInside(const PointCloud& cloud, const FlightBox& box) {
    std::size_t inside = 0, seen = 0;
    for (std::size_t i = 0; i < cloud.size(); i += 16, ++seen) inside += box.contains(cloud[i]);
    return 3 * inside > seen;
}

/// Sparse-cloud mode, ascending: edges read on riser tops are raised to the treads behind them
/// (TreadHeights); then, when the first edge reads less than a rise above the surface in front of
/// it (or the robot's floor at floor_z), all of them onto the line from that surface inside the
/// bounds of the rays that cleared them (StartSurface), else onto the line inside those bounds
/// alone (RayClearance); then the remaining low ones onto the flight's nosing line (RiserHits).
void correctRiserTopEdges(const PointCloud& cloud, StairDirection dir, double floor_z,
                          std::vector<LineSegment>& edges) {
    if (dir == StairDirection::Ascending && edges.size() >= 2) {
        const Staircase probe = makeStaircase(edges, dir, 0.0);
        const double rise = probe.step_height, run = probe.step_depth;
        // Each step looks only at the points near the flight (or, for the start, in front of
        // it), in its own box: the points in a box holding both corrections' boxes, or the whole
        // cloud when that would crop little (same result); the start's window in one pass with
        // it. The start's box reaches a rise under the first edge, the floor's points around the
        // flight would make the corrections' box several times fuller.
        const FlightBox box = bothCorrectionsBox(edges, rise, run);
        FlightBox front = startWindowBox(edges, rise, run);
        front.z_hi += TreadHeightParams().max_raise_fraction * rise;  // the first edge may rise
        const bool crop = !mostlyInside(cloud, box);
        const FloatBounds either = floatBounds(box, front);
        PointCloud near_flight, in_front;
        for (const Eigen::Vector3f& q : cloud) {
            if (!either.mayContain(q)) continue;
            if (crop && box.contains(q)) near_flight.push_back(q);
            if (front.contains(q)) in_front.push_back(q);
        }
        const PointCloud& points = crop ? near_flight : cloud;
        raiseEdgesToTreads(points, rise, run, edges);
        const std::vector<double> upper = edgeClearances(points, edges, rise, run);
        const std::optional<double> start = lowEdgesStart(in_front, edges, rise, run, floor_z);
        if (!start || !fitEdgesOnStartSurface(*start, upper, rise, edges))
            fitEdgesToRayClearance(upper, rise, edges);
    }
    raiseLowEdges(edges, kRiserHitMinDrop);
}

/// The continuation tests' parameters, their rise floor condition 1's.
FlightContinuationParams continuationParams(const DetectorParams& p) {
    FlightContinuationParams cp;
    cp.min_rise_m = p.min_step_height_m;
    return cp;
}

/// A chain one edge short of min_steps (ascending, real z, corrected): the foot of a longer flight
/// when the cloud shows the tread above its last edge (the next nosing is added) or below a first
/// edge two rises up (the previous one is added), or a flight from a raised landing
/// (FlightContinuation); else it may be a stage. Returns whether `edges` now count as a flight.
bool continueShortChain(const PointCloud& cloud, double floor_z, const DetectorParams& p,
                        std::vector<LineSegment>& edges) {
    const FlightContinuationParams cp = continuationParams(p);
    // A ramp's ring lines pass these tests too; asked once one passes (a pass over the cloud).
    const auto ramp = [&] { return treadsRiseAlongTheRun(cloud, edges, cp); };
    if (treadAboveLastEdge(cloud, edges, cp)) {
        if (ramp()) return false;
        edges.push_back(nextNosing(edges));
        return true;
    }
    if (treadBelowFirstEdge(cloud, edges, floor_z, cp)) {
        if (ramp()) return false;
        edges.insert(edges.begin(), previousNosing(edges));
        return true;
    }
    return startsFromRaisedLanding(cloud, edges, floor_z, cp) && !ramp();
}

/// A chain one edge short of min_steps (as above) whose next step's riser the cloud shows above
/// its last edge (FlightContinuation): the next nosing is added. Asked after every other
/// continuation: a chain continued by lines every other step beyond it is a whole flight, this
/// cue adds one step, and the chain's lines, once taken, continue nothing else (check7 r0174: a
/// 13-step flight, found whole by the lines beyond, was split in two when this came first).
bool continuedByNextRiser(const PointCloud& cloud, const DetectorParams& p,
                          std::vector<LineSegment>& edges) {
    const FlightContinuationParams cp = continuationParams(p);
    if (!riserAboveLastEdge(cloud, edges, cp) || treadsRiseAlongTheRun(cloud, edges, cp))
        return false;
    edges.push_back(nextNosing(edges));
    return true;
}

/// Whether a short chain can be continued at all: none put back in between, a regular straight
/// flight (the point-free test, before any pass over the cloud).
bool mayContinue(const std::vector<LineSegment>& edges, const DetectorParams& p) {
    return static_cast<int>(edges.size()) == p.min_steps - 1 &&
           isRegularStraightChain(edges, continuationParams(p));
}

/// A descending chain one edge short of min_steps whose floor edge was not found (cropped out of
/// an elevation map, hidden, or the flight starts from a landing below the floor) counts when its
/// first nosing lies a full rise (less its noise) or more below the floor: the floor's or
/// landing's edge above it is then its unseen top nosing. Steps into a pit read their first
/// nosing 0.6-0.75 rises below the floor (dev2 r0024, dev3 r0081). (Asking for a regular straight
/// chain as well, like the ascending continuation, kept none of the four dev flights it finds.)
bool impliesTopNosing(const std::vector<LineSegment>& edges, double floor_z,
                      const DetectorParams& p) {
    if (static_cast<int>(edges.size()) != p.min_steps - 1 || edges.size() < 2) return false;
    const double rise = (edges.front().z - edges.back().z) / static_cast<double>(edges.size() - 1);
    return floor_z - edges.front().z >= rise - kFlightRiseNoise;
}

/// A descending chain of two nosings below the floor with the floor's edge measured above them
/// (`edges`, real z, floor edge first), too short for min_steps, counts when the three are a
/// regular flight and nothing at all is seen one step beyond its lowest edge: the view ends
/// there (an elevation map cropped at +-4 m two steps down the flight: dev r0007, r0089), where
/// steps into a pit would show its floor and a longer flight its next tread.
bool descendsToViewEnd(const PointCloud& cloud, double floor_z, const DetectorParams& p,
                       const std::vector<LineSegment>& edges) {
    if (static_cast<int>(edges.size()) != p.min_steps - 1) return false;
    std::vector<LineSegment> mirrored = edges;  // descending = ascending in mirrored z
    for (LineSegment& e : mirrored) e.z = 2 * floor_z - e.z;
    return nothingBeyondLastEdge(cloud, mirrored, continuationParams(p));
}

/// One direction's flights from the lines of `cells`, leaving out the lines on `found_before`.
void detectDirection(const PointCloud& cloud, const Candidates& cand,
                     StairDirection dir, double floor_z, const DetectorParams& p,
                     const std::vector<Staircase>& found_before, std::vector<Staircase>& out,
                     DetectorDebug* debug, std::vector<LineSegment>& raw_lines) {
    const bool up = dir == StairDirection::Ascending;
    std::vector<LineSegment> lines = extractLines(cand, up ? kFrontDrop : kBackDrop, floor_z, p);
    if (!found_before.empty())
        lines.erase(std::remove_if(lines.begin(), lines.end(),
                                   [&](const LineSegment& l) {
                                       return onAnyFlightFootprint(l.centre(), found_before);
                                   }),
                    lines.end());
    raw_lines = lines;  // real z, for the spiral search
    if (!up) {
        // Descending = ascending in mirrored z.
        for (auto& l : lines) l.z = 2 * floor_z - l.z;
        std::sort(lines.begin(), lines.end(),
                  [](const LineSegment& a, const LineSegment& b) { return a.z < b.z; });
    }
    // A descending flight's first edge is the floor's own nosing, found after the search: the
    // search may stop one edge short of min_steps, and the flight counts once that edge is added.
    DetectorParams search = p;
    if (!up) search.min_steps = std::max(2, p.min_steps - 1);
    // The last pass (ascend_from_below_floor) asks only its own cues: the passes before it asked
    // the others of the same lines.
    const bool earlier_cues = !p.ascend_from_below_floor;
    const bool deep_treads = up && earlier_cues && p.max_level_tread_depth_m > p.max_step_depth_m;
    const bool pairs_apart = up && earlier_cues && p.max_double_step_rise_m > 0;
    std::vector<int> refused;
    std::vector<std::vector<int>> refused_ties;
    std::vector<char> used;
    const auto chains = searchStaircases(lines, floor_z, p.floor_tolerance_m, search, &refused,
                                         debug || deep_treads || pairs_apart ? &used : nullptr, up,
                                         up ? &refused_ties : nullptr);
    SpacingLevelParams spacing_levels;
    spacing_levels.min_run_m = p.min_step_depth_m;
    spacing_levels.max_run_m = p.max_step_depth_m;
    spacing_levels.min_rise_m = p.min_step_height_m - kFlightRiseNoise;
    spacing_levels.max_rise_m = p.max_step_height_m + kFlightRiseNoise;
    spacing_levels.height_min_rise_m = p.min_step_height_m;
    const auto edgesOf = [&](const std::vector<LineSegment>& from, const std::vector<int>& chain) {
        std::vector<LineSegment> edges;
        for (int idx : chain) {
            edges.push_back(from[idx]);
            if (!up) edges.back().z = 2 * floor_z - edges.back().z;
        }
        // edges the search stepped over: by the lines' spacing where riser hits' heights
        // disagree (ascending flights: a LiDAR looks down at the treads of descending ones)
        if (!up || !p.level_by_line_spacing || fillNosingsBySpacing(edges, spacing_levels) == 0)
            fillMissingNosings(edges, p.min_step_height_m);
        return edges;
    };
    // Riser hits admitted by the height tolerance are raised onto the flight's nosing line.
    const auto correct = [&](std::vector<LineSegment>& edges) {
        if (p.edge_height_tolerance_m > 0) correctRiserTopEdges(cloud, dir, floor_z, edges);
    };
    for (const auto& chain : chains) {
        std::vector<LineSegment> edges = edgesOf(lines, chain);
        if (!up) dropCropLineEnd(cloud, edges);  // an elevation map's crop on the floor below
        correct(edges);
        if (!up) prependFloorNosing(cand.cells, floor_z, p, edges);
        if (static_cast<int>(edges.size()) < p.min_steps &&
            (up || !impliesTopNosing(edges, floor_z, p))) {
            if (debug && debug->rejected.size() < DetectorDebug::kMaxRejected)
                debug->rejected.push_back({dir, edges, tooFewSteps(edges.size(), p.min_steps) +
                                                           " (no floor nosing)"});
            continue;
        }
        out.push_back(makeStaircase(edges, dir, 0.5 * p.leaf_size_m));
    }
    // The chain that ended the search one edge short, or another as long, when `counts` says its
    // edges are a flight (it may add the edge it continues with). Returns the chain taken.
    // `may` is a point-free test of the uncorrected edges that `counts` needs to pass.
    const auto anyChain = [](const std::vector<LineSegment>&) { return true; };
    // A chain's corrected edges (a pass over the cloud each) are kept for the next continuation
    // asked of it: the same chains are asked up to three times.
    std::map<std::pair<const void*, const void*>, std::vector<LineSegment>> corrected_chains;
    const auto continueRefused = [&](const std::vector<LineSegment>& from,
                                     const std::vector<int>& first,
                                     const std::vector<std::vector<int>>& ties, const auto& counts,
                                     const auto& may) -> const std::vector<int>* {
        if (static_cast<int>(first.size()) != p.min_steps - 1) return nullptr;
        for (std::size_t k = 0; k <= ties.size(); ++k) {
            const std::vector<int>& chain = k == 0 ? first : ties[k - 1];
            std::vector<LineSegment> edges = edgesOf(from, chain);
            if (!mayContinue(edges, p) || !may(edges)) continue;
            const auto key = std::make_pair<const void*, const void*>(&from, &chain);
            if (const auto it = corrected_chains.find(key); it != corrected_chains.end()) {
                edges = it->second;
            } else {
                correct(edges);
                corrected_chains.emplace(key, edges);
            }
            if (counts(edges)) {
                out.push_back(makeStaircase(edges, dir, 0.5 * p.leaf_size_m));
                return &chain;
            }
        }
        return nullptr;
    };
    const auto continued = [&](std::vector<LineSegment>& edges) {
        return continueShortChain(cloud, floor_z, p, edges);
    };
    // Only where no chain continues so: then the lines every other step beyond a chain of three
    // (FlightContinuation.h) continue it, each with the nosing halfway before it put back. Off the
    // flights found: there such a chain is a piece of one of them.
    std::vector<int> beyond;
    const auto continuedEveryOtherStep = [&](std::vector<LineSegment>& edges) {
        const auto onFound = [&](const LineSegment& e) {
            return onAnyFlightFootprint(e.centre(), out);
        };
        if (std::any_of(edges.begin(), edges.end(), onFound)) return false;
        beyond = linesEveryOtherStepBeyond(lines, edges, continuationParams(p));
        if (!beyond.empty() && treadsRiseAlongTheRun(cloud, edges, continuationParams(p)))
            beyond.clear();  // a ramp's ring lines
        if (beyond.empty()) return false;
        for (int k : beyond) {
            edges.push_back(halfwayNosing(edges.back(), lines[k]));
            edges.push_back(lines[k]);
        }
        correct(edges);  // the new lines are riser hits as often as the chain's were
        return true;
    };
    if (up) {
        const std::vector<int>* taken =
            earlier_cues ? continueRefused(lines, refused, refused_ties, continued, anyChain)
                         : nullptr;
        // Its corrections are a pass over the cloud each: only for chains with a line already
        // two steps beyond their uncorrected last edge.
        const auto lineBeyond = [&](const std::vector<LineSegment>& edges) {
            return !linesEveryOtherStepBeyond(lines, edges, continuationParams(p)).empty();
        };
        if (!taken && earlier_cues && p.continue_every_other_step)
            taken =
                continueRefused(lines, refused, refused_ties, continuedEveryOtherStep, lineBeyond);
        if (!taken && earlier_cues && p.continue_by_next_riser) {
            beyond.clear();
            const auto byRiser = [&](std::vector<LineSegment>& edges) {
                return continuedByNextRiser(cloud, p, edges);
            };
            taken = continueRefused(lines, refused, refused_ties, byRiser, anyChain);
        }
        // Last (the passes before this one found their flights): a chain one rise up from the
        // floor, rising from the tread a rise below it, gets its nosing at the floor's height.
        if (!taken && p.ascend_from_below_floor) {
            beyond.clear();
            const auto abovePit = [&](std::vector<LineSegment>& edges) {
                const FlightContinuationParams cp = continuationParams(p);
                if (!floorNosingAbovePit(cloud, edges, floor_z, cp) ||
                    treadsRiseAlongTheRun(cloud, edges, cp))
                    return false;
                edges.insert(edges.begin(), previousNosing(edges));
                return true;
            };
            taken = continueRefused(lines, refused, refused_ties, abovePit, anyChain);
        }
        if (taken) {
            if (!used.empty()) {  // kept only for the searches below and the debug record
                for (int idx : *taken) used[idx] = 1;
                for (int idx : beyond) used[idx] = 1;
            }
            refused.clear();  // not a refusal after all
        }
    }
    if (!up && static_cast<int>(refused.size()) == search.min_steps - 1) {
        std::vector<LineSegment> edges = edgesOf(lines, refused);
        correct(edges);
        const std::size_t below_floor = edges.size();
        prependFloorNosing(cand.cells, floor_z, p, edges);
        if (edges.size() == below_floor + 1 && descendsToViewEnd(cloud, floor_z, p, edges)) {
            out.push_back(makeStaircase(edges, dir, 0.5 * p.leaf_size_m));
            if (!used.empty())
                for (int idx : refused) used[idx] = 1;
            refused.clear();  // not a refusal after all
        }
    }
    // The lines Algorithm 1's chains left, for the two searches below (neither marks lines used).
    std::vector<LineSegment> rest;
    if (deep_treads || pairs_apart)
        for (std::size_t i = 0; i < lines.size(); ++i)
            if (!used[i]) rest.push_back(lines[i]);
    // Deep treads (LongTreads.h): the search again on the lines left, with runs up to
    // max_level_tread_depth_m; a chain beyond the usual bound counts where its treads are level.
    if (deep_treads) {
        DetectorParams deep = search;
        deep.max_step_depth_m = p.max_level_tread_depth_m;
        deep.min_slope_deg = p.min_level_tread_slope_deg;
        std::vector<int> deep_refused;
        std::vector<std::vector<int>> deep_ties;
        const auto isDeepLevel = [&](const std::vector<LineSegment>& edges, double min_run,
                                     const LevelTreadParams& lp) {
            return meanRun(edges) > min_run && treadsSeenLevel(cloud, edges, lp);
        };
        const auto beyondBound = [&](const std::vector<LineSegment>& edges) {
            return isDeepLevel(edges, p.max_step_depth_m, LevelTreadParams{});
        };
        LevelTreadParams seen_densely;  // only then does an empty patch mean nothing there
        seen_densely.min_points_per_m2 = kDenseTreadPointsPerM2;
        for (const auto& chain : searchStaircases(rest, floor_z, p.floor_tolerance_m, deep,
                                                  &deep_refused, nullptr, up, &deep_ties)) {
            std::vector<LineSegment> edges = edgesOf(rest, chain);
            correct(edges);
            if (beyondBound(edges)) out.push_back(makeStaircase(edges, dir, 0.5 * p.leaf_size_m));
        }
        // A chain one edge short counts as usual (continueShortChain) when beyond the bound, and
        // also when its treads are min_deep_tread_m deep and nothing is seen one step beyond its
        // last edge (the real ANYmal entrance from its landing: the top tread's far part is
        // unmapped), where a stage's platform would be seen.
        continueRefused(
            rest, deep_refused, deep_ties,
            [&](std::vector<LineSegment>& edges) {
                if (beyondBound(edges) && continued(edges)) return true;
                return isDeepLevel(edges, p.min_deep_tread_m, seen_densely) &&
                       unseenBeyondLastEdge(cloud, edges, continuationParams(p));
            },
            anyChain);
    }
    // Ring-aliased flights (DetectorParams::max_double_step_rise_m): the search again on the
    // lines left, for pairs two steps apart; the skipped nosings are put back halfway.
    if (pairs_apart) {
        DetectorParams two_steps = search;
        two_steps.min_step_height_m = 2 * p.min_step_height_m;
        two_steps.max_step_height_m = p.max_double_step_rise_m;
        two_steps.min_step_depth_m = 2 * p.min_step_depth_m;
        two_steps.max_step_depth_m = 2 * p.max_step_depth_m;
        for (const auto& chain : searchStaircases(rest, floor_z, p.floor_tolerance_m, two_steps,
                                                  nullptr, nullptr, up, nullptr)) {
            std::vector<LineSegment> edges = edgesOf(rest, chain);
            if (treadsSeenLevel(cloud, edges)) continue;  // deep level treads: no step between
            if (!putBackEveryOtherNosing(lines, edges)) continue;
            correct(edges);
            Staircase flight = makeStaircase(edges, dir, 0.5 * p.leaf_size_m);
            // On a flight found already, such a chain is that flight's lines read at half its
            // rise (a riser hit or side-wall ring between its nosings: dev3 r0016, 0.20 m rises
            // read 0.123 m); its put-back steps would make it the longer one and replace it.
            if (overlapsAnyFlight(flight, out)) continue;
            out.push_back(std::move(flight));
        }
    }
    if (debug) recordDirection(lines, used, refused, dir, floor_z, p, *debug);
}

/// [m] a spiral's lowest nosing this much less than its rise above the floor reads low
constexpr double kLowSpiralFootMargin = 0.03;

/// Sparse-cloud mode: a spiral seen by a level LiDAR's riser hits only (dev3 r0222, a VLP-16 at
/// 3.4 m) has every edge low by 2-11 cm, its lowest less than a rise above the floor; the straight
/// flights' corrections (correctRiserTopEdges) put them onto the line from the floor. Only then:
/// applied to every spiral they moved the rise of spirals seen well, starting above the floor
/// (dev2 r0197: 0.4 -> 1.3 cm off).
void correctLowSpiralFoot(const PointCloud& cloud, double floor_z,
                          std::vector<LineSegment>& edges) {
    if (edges.size() < 2) return;
    const double rise = makeStaircase(edges, StairDirection::Ascending, 0.0).step_height;
    if (edges.front().z - floor_z < rise - kLowSpiralFootMargin)
        correctRiserTopEdges(cloud, StairDirection::Ascending, floor_z, edges);
}

/// Whether most of flight `s`'s edges lie on spiral `f` (within its outer radius plus 0.15 m and
/// a rise `max_rise_m` of its height range).
bool liesOnSpiral(const Staircase& s, const SpiralFlight& f, double max_rise_m) {
    const double z_lo = f.edges.front().z - max_rise_m;
    const double z_hi = f.edges.back().z + max_rise_m;
    int inside = 0;
    for (const StairEdge& e : s.steps) {
        const Eigen::Vector3d c = e.centre();
        inside +=
            (c.head<2>() - f.axis).norm() < f.outer_radius_m + 0.15 && c.z() > z_lo && c.z() < z_hi;
    }
    return 2 * inside > static_cast<int>(s.steps.size());
}

/// A found spiral as a flight (its lowest nosing corrected when read low).
Staircase spiralStaircase(const PointCloud& cloud, const SpiralFlight& f, double floor_z,
                          const DetectorParams& p) {
    std::vector<LineSegment> edges = f.edges;
    if (p.edge_height_tolerance_m > 0) correctLowSpiralFoot(cloud, floor_z, edges);
    Staircase s = makeStaircase(edges, StairDirection::Ascending, 0.5 * p.leaf_size_m);
    // The run at mid radius from the found lines: StepExtent's tread windows use it, and it is
    // measured again from the measured edges (TurningFlight).
    s.step_depth = f.run_m;
    s.slope_rad = std::atan2(s.step_height, f.run_m);
    return s;
}

/// Spiral `f` (as `flight`) replaces the flights lying on it unless one of them has more steps.
void placeSpiral(const SpiralFlight& f, Staircase flight, double max_rise_m,
                 std::vector<Staircase>& out) {
    const auto on = [&](const Staircase& s) { return liesOnSpiral(s, f, max_rise_m); };
    for (const Staircase& s : out)
        if (on(s) && s.steps.size() > f.edges.size()) return;
    out.erase(std::remove_if(out.begin(), out.end(), on), out.end());
    out.push_back(std::move(flight));
}

/// The spiral search's bounds from the detector's (conditions 1 and 2, the initialisation height).
SpiralSearchParams spiralParams(double floor_z, const DetectorParams& p) {
    SpiralSearchParams sp;
    sp.floor_z = floor_z;
    sp.min_first_height_m = p.floor_tolerance_m;
    sp.max_first_height_m = p.init_height_factor * p.max_step_height_m;
    sp.min_rise_m = p.min_step_height_m;
    sp.low_rise_noise_m = kFlightRiseNoise;  // one noise bound for straight flights and spirals
    sp.max_rise_m = p.max_step_height_m;
    sp.min_run_m = p.min_step_depth_m;
    sp.max_run_m = p.max_step_depth_m;
    sp.min_steps = p.min_steps;
    return sp;
}

/// [-] the treads are looked at only about an axis the first search glimpsed through this many
/// seen levels: 3 glimpses in 16 % of the development clouds (2: 44 %), and as many dev spirals
/// are found as when every cloud's surface about the robot was looked at
constexpr int kTreadGlimpseLevels = 3;

/// Spirals found by their axis (SpiralSearch). A spiral replaces the chains of Algorithm 1 on its
/// steps (in its column's radius and height range) unless one of them has more steps. With
/// `few_level` given, the spirals of p.few_level_spiral_levels seen levels go there, to be placed
/// once every pass has run (placeFewLevelSpirals), and so do those read from the treads about an
/// axis glimpsed (TreadSpirals).
void addSpiralFlights(const PointCloud& cloud, const std::vector<LineSegment>& front_drops,
                      const std::vector<LineSegment>& back_drops, double floor_z,
                      const DetectorParams& p, std::vector<Staircase>& out,
                      std::vector<Staircase>* few_level) {
    SpiralSearchParams sp = spiralParams(floor_z, p);
    sp.few_seen_levels = p.few_level_spiral_levels;
    std::vector<SpiralFlight> few;
    SpiralGlimpse glimpse;
    const bool treads = few_level && p.tread_spiral_cell_m > 0;
    for (const SpiralFlight& f : findSpirals(
             front_drops, back_drops, sp, few_level ? &few : nullptr, treads ? &glimpse : nullptr))
        placeSpiral(f, spiralStaircase(cloud, f, floor_z, p), p.max_step_height_m, out);
    if (!few_level) return;
    for (const SpiralFlight& f : few) few_level->push_back(spiralStaircase(cloud, f, floor_z, p));
    // An axis glimpsed on a flight found already is that flight seen again (dev5: 196 of 1,200
    // clouds look at their treads without this, 43 with it, finding the same spirals).
    if (treads && glimpse.seen_levels >= kTreadGlimpseLevels &&
        !onAnyFlightFootprint(glimpse.axis, out))
        for (const SpiralFlight& f : findTreadSpirals(
                 cloud, glimpse.axis, front_drops, back_drops, sp,
                 {p.tread_spiral_cell_m, p.tread_spiral_window_m, p.max_height_above_floor_m}))
            few_level->push_back(spiralStaircase(cloud, f, floor_z, p));
}

/// The spirals of few seen levels (DetectorParams::few_level_spiral_levels) that no flight found
/// by any pass overlaps: where one does, it is the same spiral found better or something else.
void placeFewLevelSpirals(std::vector<Staircase>& few_level, std::vector<Staircase>& found) {
    for (Staircase& s : few_level)
        if (!overlapsAnyFlight(s, found)) found.push_back(std::move(s));
}

FlightJoinParams joinParams(const DetectorParams& p) {
    FlightJoinParams jp;
    jp.max_heading_diff_deg = std::min(15.0, p.max_parallel_deg);
    jp.height_tolerance_m = std::max(p.edge_height_tolerance_m, 0.02);
    return jp;
}

/// Algorithm 1 both ways on the lines of `cells` (rows of p.row_height_m) off the flights in
/// `found_before`, the detector's merges of its own chains, then the spirals (those of few seen
/// levels into `few_level_spirals` when given). `user` are the parameters as given (p may have a
/// raised split distance or other rows).
std::vector<Staircase> findFlights(const PointCloud& cloud, const Candidates& cand, double floor_z,
                                   const DetectorParams& p, const DetectorParams& user,
                                   const std::vector<Staircase>& found_before, DetectorDebug* debug,
                                   std::vector<Staircase>* few_level_spirals = nullptr) {
    std::vector<Staircase> found;
    std::vector<LineSegment> front_drops, back_drops;  // real z, for the spiral search
    if (p.detect_ascending)
        detectDirection(cloud, cand, StairDirection::Ascending, floor_z, p, found_before, found,
                        debug, front_drops);
    if (p.detect_descending)
        detectDirection(cloud, cand, StairDirection::Descending, floor_z, p, found_before, found,
                        debug, back_drops);
    mergeOverlappingFlights(found);  // Algorithm 2 on the detector's own chains
    joinContinuedFlights(found, joinParams(user));
    // After the merges, which compare the edges of straight flights.
    if (user.detect_ascending)
        addSpiralFlights(cloud, front_drops, back_drops, floor_z, user, found, few_level_spirals);
    return found;
}

/// [-] the tilted-ring pass's flights rise evenly: every pair of consecutive edges within this
/// fraction of the flight's rise. Its 5 cm rows chain a furnished room's box and shelf edges seen
/// by a depth camera into "steps" of 0.32, 0.11 and 0.23 m (negatives of seed 26026, r1160); no
/// flight the pass adds on dev-dev6 is lost at this bound, and of all 2,516 flights found there
/// 19 have a pair further off (joins across unseen steps, riser hits of other passes).
constexpr double kTiltedPassMaxRiseDeviation = 0.35;

/// Whether every pair of consecutive edges of `s` rises within max_deviation x s.step_height of
/// its rise.
bool risesEvenly(const Staircase& s, double max_deviation) {
    for (std::size_t i = 1; i < s.steps.size(); ++i) {
        const double rise = std::abs(s.steps[i].centre().z() - s.steps[i - 1].centre().z());
        if (std::abs(rise - s.step_height) > max_deviation * s.step_height) return false;
    }
    return true;
}

/// `p` with the tilted-ring pass's taller rows (DetectorParams::tilted_ring_row_height_m).
DetectorParams tiltedRingParams(const DetectorParams& p, const DetectorParams& user) {
    DetectorParams tall = p;
    tall.row_height_m = user.tilted_ring_row_height_m;
    return tall;
}

/// The tilted-ring pass (DetectorParams::tilted_ring_row_height_m): the search again with taller
/// rows on the lines off the flights found; its flights that keep off those too and rise evenly
/// (kTiltedPassMaxRiseDeviation) are added.
void addTiltedRingFlights(const PointCloud& cloud, const Candidates& cand,
                          double floor_z, const DetectorParams& p, const DetectorParams& user,
                          std::vector<Staircase>& found) {
    const DetectorParams tall = tiltedRingParams(p, user);
    // Condition 1 outright (without dropFlightsOutsideTheRises's 2 cm of noise): a ramp beside a
    // pitched LiDAR, its slanted rings cut by the taller rows, reads as 0.099 m rises (check
    // r0165); the pass's flights on the three development sets read 0.11 m or more but one.
    for (Staircase& s : findFlights(cloud, cand, floor_z, tall, user, found, nullptr))
        if (!overlapsAnyFlight(s, found) && s.step_height >= user.min_step_height_m &&
            risesEvenly(s, kTiltedPassMaxRiseDeviation))
            found.push_back(std::move(s));
    // A flight the first pass found in part may go on beyond its footprint (dev2 r0008: its
    // upper seven steps, seen by the tilted rings only).
    joinContinuedFlights(found, joinParams(user));
}

/// Condition 1 on whole flights. The sparse-mode tolerance admits single pairs read low by riser
/// hits; once corrected, a flight's rise is measured over all its steps, and one still below
/// condition 1 (less kFlightRiseNoise) is no stair: a 14 deg ramp's ring hits read as a flight of
/// 0.078 m rises (dev3 r0265, a negative). Real flights of 0.10-0.11 m rises read 0.096-0.107 m.
/// Likewise above condition 1 (plus kFlightRiseNoise): the tolerance lets bleachers' 0.375 m tiers
/// seen through a pitched LiDAR's slanted rings chain into a flight reading 0.356 m rises
/// (negatives set 5005, r0687); no found flight on the dev sets reads above 0.32 m.
void dropFlightsOutsideTheRises(const DetectorParams& p, std::vector<Staircase>& flights) {
    const double min_rise = p.min_step_height_m - kFlightRiseNoise;
    const double max_rise = p.max_step_height_m + kFlightRiseNoise;
    const auto outside = [&](const Staircase& s) {
        return s.step_height < min_rise || s.step_height > max_rise;
    };
    flights.erase(std::remove_if(flights.begin(), flights.end(), outside), flights.end());
}

/// [deg] a flight whose edges all lie within this of its last edge's direction is straight enough
/// for the ramp test below: Algorithm 1's chains through spirals turn 30-90 deg over their steps
/// (and their points lie off a straight stair's profile), a ramp's ring lines 9-18 deg (check4
/// r0150); straight flights turn 0-16 deg (dev sets)
constexpr double kRampTestMaxTurnDeg = 25.0;

/// [deg] a ramp's ring lines lie on its surface: their flight reads about the ramp's slope (5-15
/// deg in the benchmark; check4 r0150's 14.8 deg ramp reads 15.3 and 16.7 deg; pitched LiDARs'
/// slanted rings on 11-15 deg ramps read 24.4-24.6 deg, check5 r0095, r0294), where a stair's is
/// 14-45 deg. Only flights this shallow are tested (the test is a pass over the cloud).
constexpr double kRampTestMaxSlopeDeg = 30.0;

/// [-] the ramp test on a whole flight looks at every n-th point of the cloud, n chosen so that
/// about this many are looked at: a ratio of two RMS distances needs no more
constexpr std::size_t kRampTestSampledPoints = 16384;

/// [-] the ramp test looks at the points over a flight's first this many edges: every part of a
/// ramp's ring-line chain lies on its slope, while a long flight's upper part seen from its side
/// shows the floor under it, far off both the stair's profile and the ramp's line (dev4 r0101: a
/// 16-step debris flight 7 m away joined across an unseen step, ramp RMS 0.37 m, stair 0.66 m)
constexpr std::size_t kRampTestMaxEdges = 8;

/// Whether all edges of `s` lie within kRampTestMaxTurnDeg of its last edge.
bool nearlyStraight(const Staircase& s) {
    const Eigen::Vector3d last = s.steps.back().end - s.steps.back().start;
    const Eigen::Vector2d d = last.head<2>().normalized();
    const double cos_max = std::cos(kRampTestMaxTurnDeg * M_PI / 180.0);
    return std::all_of(s.steps.begin(), s.steps.end(), [&](const StairEdge& e) {
        return std::abs((e.end - e.start).head<2>().normalized().dot(d)) >= cos_max;
    });
}

/// The edges of flight `s` as lines (unseenNosing: geometry only), for the chain tests.
std::vector<LineSegment> edgeLines(const Staircase& s) {
    std::vector<LineSegment> edges;
    for (const StairEdge& e : s.steps)
        edges.push_back(unseenNosing(e.start.head<2>(), e.end.head<2>(), e.start.z()));
    return edges;
}

/// Whether ascending flight `s`, shallow and nearly straight, has its points on one sloped surface
/// (treadsRiseAlongTheRun asked with `max_rms_ratio`, over its first kRampTestMaxEdges edges).
bool isRampFlight(const PointCloud& cloud, const Staircase& s, double max_rms_ratio) {
    if (s.direction != StairDirection::Ascending || s.steps.size() < 2 ||
        s.slope_rad > kRampTestMaxSlopeDeg * M_PI / 180.0 || !nearlyStraight(s))
        return false;
    FlightContinuationParams cp;
    cp.ramp_max_rms_ratio = max_rms_ratio;
    cp.ramp_point_stride =
        std::max<int>(1, static_cast<int>(cloud.size() / kRampTestSampledPoints));
    std::vector<LineSegment> edges = edgeLines(s);
    if (edges.size() > kRampTestMaxEdges) edges.resize(kRampTestMaxEdges);
    return treadsRiseAlongTheRun(cloud, edges, cp);
}

/// Ascending flights whose points lie on one sloped surface (treadsRiseAlongTheRun, asked with
/// p.max_ramp_rms_ratio) are a ramp's ring lines: a LiDAR's rings cross a ramp a "rise" apart and
/// four or five of them chain like nosings (check4 r0150, a 14.8 deg ramp 4 m from a level
/// HDL-32: ratios 0.46 and 0.15). Found flights on the dev sets read 0.75 and more. (Descending
/// flights in mirrored z lost three dev flights seen from above at the same bound: not asked.)
void dropRampFlights(const PointCloud& cloud, const DetectorParams& p,
                     std::vector<Staircase>& flights) {
    if (p.max_ramp_rms_ratio <= 0) return;
    const auto ramp = [&](const Staircase& s) {
        return isRampFlight(cloud, s, p.max_ramp_rms_ratio);
    };
    flights.erase(std::remove_if(flights.begin(), flights.end(), ramp), flights.end());
}

/// Descending flights whose first edge lies below the floor on a slope (descentStartsOnASlope,
/// asked with p.max_descent_start_off_level) are a ramp's ring lines seen from its top.
void dropDescentsFromASlope(const PointCloud& cloud, double floor_z, const DetectorParams& p,
                            std::vector<Staircase>& flights) {
    if (p.max_descent_start_off_level >= 1.0) return;
    DescentStartParams dp;
    dp.max_off_level_fraction = p.max_descent_start_off_level;
    const auto on_slope = [&](const Staircase& s) {
        return descentStartsOnASlope(cloud, s, floor_z, dp);
    };
    flights.erase(std::remove_if(flights.begin(), flights.end(), on_slope), flights.end());
}

/// Whether flight `s` is a regular straight flight (isRegularStraightChain with the edges within
/// kRampTestMaxTurnDeg of the last; descending flights in mirrored z about `floor_z`).
bool isRegularFlight(const Staircase& s, double floor_z) {
    std::vector<LineSegment> edges = edgeLines(s);
    if (s.direction == StairDirection::Descending)
        for (LineSegment& e : edges) e.z = 2 * floor_z - e.z;  // ascending in mirrored z
    FlightContinuationParams cp;
    cp.max_turn_deg = kRampTestMaxTurnDeg;
    return isRegularStraightChain(edges, cp);
}

/// A pass of looser lines (`loose`: the dashed-nosing and sparse-line passes): Algorithm 1 on the
/// lines off the flights found, its flights added when they keep off those, have min_steps edges
/// or more (a descending chain of min_steps - 1 and the floor's edge is not enough for looser
/// lines: dashes of a pitched VLP-16's rings joined across a flight's side, dev3 r0270),
/// condition 1's rise, are no ramp at the short chains' bound (FlightContinuationParams::
/// ramp_max_rms_ratio 0.8: the dashed pass's flights on the dev sets read 1.13-2.2, a 14 deg ramp
/// beside a pitched VLP-16 0.70, check2 r0234) and, when `straight_only`, a regular straight
/// flight. The spiral search is not asked (user's detect_ascending off: the first passes had
/// their lines).
void addLooseFlights(const PointCloud& cloud, const Candidates& cand, double floor_z,
                     const DetectorParams& loose, const DetectorParams& user, bool straight_only,
                     std::vector<Staircase>& found) {
    DetectorParams no_spirals = user;
    no_spirals.detect_ascending = false;
    const double ramp_ratio = FlightContinuationParams{}.ramp_max_rms_ratio;
    for (Staircase& s : findFlights(cloud, cand, floor_z, loose, no_spirals, found, nullptr))
        if (static_cast<int>(s.steps.size()) >= user.min_steps &&
            s.step_height >= user.min_step_height_m && !overlapsAnyFlight(s, found) &&
            (!straight_only || isRegularFlight(s, floor_z)) && !isRampFlight(cloud, s, ramp_ratio))
            found.push_back(std::move(s));
    joinContinuedFlights(found, joinParams(user));
}

/// `p` with the dashed-nosing pass's rows, cut only at gaps over dashed_nosing_gap_m, `rows` tall.
DetectorParams dashedNosingParams(const DetectorParams& p, const DetectorParams& user,
                                  double rows) {
    DetectorParams dashed = p;
    dashed.max_point_gap_m = user.dashed_nosing_gap_m;
    dashed.row_height_m = rows;
    return dashed;
}

/// `p` with the sparse-line pass's lines of fewer points (DetectorParams::sparse_line_points).
DetectorParams sparseLineParams(const DetectorParams& p, const DetectorParams& user) {
    DetectorParams sparse = p;
    sparse.min_line_points = user.sparse_line_points;
    return sparse;
}

/// The dashed-nosing pass (DetectorParams::dashed_nosing_gap_m): Algorithm 1 with rows cut only
/// at long gaps, at both row heights, its flights those of a pass of looser lines that are
/// regular straight flights (chains through a spiral's levels and balusters read rises 10 cm off,
/// dev3 r0014; on the check sets a chain over every other level of an open-riser flight, check3
/// r0291).
void addDashedNosingFlights(const PointCloud& cloud, const Candidates& cand, double floor_z,
                            const DetectorParams& p, const DetectorParams& user,
                            std::vector<Staircase>& found) {
    if (user.dashed_nosing_gap_m <= 0) return;
    for (const double rows : {user.row_height_m, user.tilted_ring_row_height_m}) {
        if (rows <= 0) continue;
        addLooseFlights(cloud, cand, floor_z, dashedNosingParams(p, user, rows), user,
                        /*straight_only=*/true, found);
    }
}

/// The sparse-line pass (DetectorParams::sparse_line_points): Algorithm 1 with lines of fewer
/// points, its flights those of a pass of looser lines that may turn: the spirals it adds on the
/// development sets are chained step by step (dev2 r0147, dev3 r0090, r0267; asking for a regular
/// straight flight, as the dashed pass does, kept two of the seven flights it finds there and none
/// of its spirals).
void addSparseLineFlights(const PointCloud& cloud, const Candidates& cand, double floor_z,
                          const DetectorParams& p, const DetectorParams& user,
                          std::vector<Staircase>& found) {
    if (user.sparse_line_points <= 0) return;
    addLooseFlights(cloud, cand, floor_z, sparseLineParams(p, user), user,
                    /*straight_only=*/false, found);
}

/// The last pass (DetectorParams::ascend_from_below_floor): Algorithm 1 again, ascending only and
/// without the spiral search, with the rows and lines of each pass before it (the first pass's,
/// the dashed-nosing pass's at both row heights, the sparse-line and tilted-ring passes'), on the
/// lines off the flights found; a chain may count the nosing at the floor's height it steps over,
/// start from the lines below the floor where the chains from it fall short, or be continued
/// down to that nosing above a pit. Kept: flights of min_steps edges or more that start below the
/// floor (what the pass is for: the others were searched already), are regular straight flights
/// (a depth camera's noisy lines chained across the floor read rises 4-10 cm off) and keep off the
/// flights found. Last, so that the other passes' readings of a flight are kept: run within them,
/// its chains of riser hits preempted whole flights (dev6 r1107, a 5-step flight read as 4).
/// Skipped when no point lies below the floor (half a minimum rise): a level room pays one scan.
void addFlightsFromBelowFloor(const PointCloud& cloud, const Candidates& cand, double floor_z,
                              const DetectorParams& p, const DetectorParams& user,
                              std::vector<Staircase>& found) {
    const double below_floor = floor_z - 0.5 * user.min_step_height_m;
    // Nothing seen below the floor (a room's level floor): no flight rises from there.
    if (std::none_of(cloud.begin(), cloud.end(),
                     [&](const Eigen::Vector3f& q) { return q.z() < below_floor; }))
        return;
    DetectorParams below = p;
    below.ascend_from_below_floor = true;
    below.detect_descending = false;
    std::vector<DetectorParams> passes = {below};
    if (user.dashed_nosing_gap_m > 0)
        for (const double rows : {user.row_height_m, user.tilted_ring_row_height_m})
            if (rows > 0) passes.push_back(dashedNosingParams(below, user, rows));
    if (user.sparse_line_points > 0) passes.push_back(sparseLineParams(below, user));
    if (user.tilted_ring_row_height_m > 0) passes.push_back(tiltedRingParams(below, user));
    DetectorParams no_spirals = user;
    no_spirals.detect_ascending = false;
    for (const DetectorParams& pass : passes)
        for (Staircase& s : findFlights(cloud, cand, floor_z, pass, no_spirals, found, nullptr))
            if (static_cast<int>(s.steps.size()) >= user.min_steps &&
                flightStartZ(s) < below_floor && isRegularFlight(s, floor_z) &&
                !overlapsAnyFlight(s, found))
                found.push_back(std::move(s));
}

/// [m/m] a profile flight's surface rising along its nosings by more than this is a ramp's ring
/// pieces (NosingSlope.h): the development ramp read so (dev5 r1079) slopes 0.195; the flights
/// the pass finds on dev-dev6 0.00-0.06, after the refits that leave walls and boxes out
constexpr double kProfileMaxNosingSlope = 0.12;

/// [m] lines and profile flights this far beside a flight found (along its nosings, within its
/// run span) are that flight's: a found flight that reads part of a wide flight's width leaves the
/// pieces beyond it, and their comb is the same flight read again at other heights (`make eval`'s
/// check set r0017: a 2.3 m wide open-riser flight read 0.62 m wide, then again beside it; seen
/// after scoring that set). 0.3 m (the other passes' margin) let it through; 1.0 and 2.0 m change
/// nothing on dev-dev6.
constexpr double kProfileBesideFlightM = 1.0;

/// Straight ascending flights read from their profile (DetectorParams::profile_flights): the
/// front-drop lines of the first, dashed and sparse passes off the flights found, their combs
/// (ProfileChains.h) corrected like other chains and kept as flights when they are no ramp's ring
/// lines (neither rising along the run nor along the nosings), no deep level treads between
/// every other nosing (bleachers' tiers), regular and off the flights found.
void addProfileFlights(const PointCloud& cloud, const Candidates& cand, double floor_z,
                       const DetectorParams& p, const DetectorParams& user,
                       std::vector<Staircase>& found) {
    if (!user.profile_flights || !user.detect_ascending) return;
    std::vector<DetectorParams> passes = {p};
    if (user.dashed_nosing_gap_m > 0)
        for (const double rows : {user.row_height_m, user.tilted_ring_row_height_m})
            if (rows > 0) passes.push_back(dashedNosingParams(p, user, rows));
    if (user.sparse_line_points > 0) passes.push_back(sparseLineParams(p, user));
    FlightFootprintParams beside;
    beside.lateral_margin_m = kProfileBesideFlightM;
    std::vector<LineSegment> lines;
    for (const DetectorParams& pass : passes)
        for (const LineSegment& l : extractLines(cand, kFrontDrop, floor_z, pass))
            if (!onAnyFlightFootprint(l.centre(), found, beside)) lines.push_back(l);
    ProfileChainParams pp;
    pp.floor_z = floor_z;
    pp.min_rise_m = user.min_step_height_m;
    pp.max_rise_m = user.max_step_height_m;
    pp.min_run_m = user.min_step_depth_m;
    pp.max_run_m = user.max_step_depth_m;
    const FlightContinuationParams cp = continuationParams(user);
    for (std::vector<LineSegment>& edges : findProfileChains(lines, pp)) {
        if (user.edge_height_tolerance_m > 0)
            correctRiserTopEdges(cloud, StairDirection::Ascending, floor_z, edges);
        if (treadsRiseAlongTheRun(cloud, edges, cp)) continue;
        const auto slope = slopeAlongNosings(cloud, edges);
        if (slope && std::abs(*slope) > kProfileMaxNosingSlope) continue;
        // Every other tier of bleachers put back: the seen edges' treads are level where a
        // skipped step would rise (as for the ring-aliased chains of detectDirection).
        std::vector<LineSegment> seen;
        bool skipped = false;
        for (const LineSegment& e : edges) {
            if (e.num_points > 0)
                seen.push_back(e);
            else if (!seen.empty())
                skipped = true;
        }
        if (skipped && treadsSeenLevel(cloud, seen)) continue;
        Staircase s = makeStaircase(edges, StairDirection::Ascending, 0.5 * p.leaf_size_m);
        if (static_cast<int>(s.steps.size()) < user.min_steps || overlapsAnyFlight(s, found, beside) ||
            !isRegularFlight(s, floor_z))
            continue;
        found.push_back(std::move(s));
    }
}

/// [m] the column is looked for this far beyond the nosings' inner ends, and this far above the
/// highest nosing (the column's top above the last tread) and kColumnBelow below the lowest
constexpr double kColumnReach = 0.10, kColumnAbove = 0.30, kColumnBelow = 0.05;

/// The column of turning flight `s` (SpiralColumn), from the points within the flight's heights.
std::optional<SpiralColumn> columnOf(const PointCloud& cloud, const Staircase& s,
                                     const TurningFlight& turning) {
    double z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
    for (const StairEdge& e : s.steps) {
        z_lo = std::min(z_lo, e.start.z());
        z_hi = std::max(z_hi, e.start.z());
    }
    return fitSpiralColumn(cloud, turning.axis, z_lo - kColumnBelow, z_hi + kColumnAbove,
                           turning.inner_radius_m + kColumnReach);
}

}  // namespace

StairDetector::StairDetector(const DetectorParams& params) : params_(params) { params_.validate(); }

DetectionResult StairDetector::detect(const PointCloud& cloud_robot, std::optional<double> floor_z,
                                      DetectorDebug* debug) const {
    DetectionResult result;
    if (debug) debug->clear();
    const auto [floor, estimated] = resolveFloor(cloud_robot, floor_z, params_);
    result.floor_z = floor;
    result.floor_estimated = estimated;
    if (debug) debug->floor_z = floor;
    if (cloud_robot.empty()) return result;

    const TopViewParams tp = topViewParams(params_, floor);
    thread_local std::vector<TopViewCell> tl_cells;  // scratch re-used between calls
    std::vector<TopViewCell>& cells = tl_cells;
    buildTopView(cloud_robot, tp, cells);
    if (debug) debug->candidates = cells;
    thread_local CylindricalRowsCache tl_arrays;  // scratch re-used between calls
    tl_arrays.clear();
    thread_local RowLinesCache tl_lines;  // scratch re-used between calls
    tl_lines.clear();
    const Candidates cand{cells, tl_arrays, tl_lines};

    // The passes' parameters; the last pass alone looks below the floor (see its comment).
    DetectorParams p = withNoisySplitDistance(params_, cloud_robot, floor, debug);
    p.ascend_from_below_floor = false;
    std::vector<Staircase> few_level_spirals;
    result.staircases =
        findFlights(cloud_robot, cand, floor, p, params_, {}, debug, &few_level_spirals);
    addDashedNosingFlights(cloud_robot, cand, floor, p, params_, result.staircases);
    addSparseLineFlights(cloud_robot, cand, floor, p, params_, result.staircases);
    // Last of the passes: its taller rows smear a riser's hits over twice the height, so its
    // flights read their rise worse than the other passes' readings of the same flight (dev5
    // r0204: 0.142 m where the dashed pass reads 0.215 m on 0.218 m rises; dev6 r0488's far
    // flight 0.190 m where it reads 0.200 m on 0.204 m). Run before them, it took their lines.
    if (params_.tilted_ring_row_height_m > 0)
        addTiltedRingFlights(cloud_robot, cand, floor, p, params_, result.staircases);
    if (params_.ascend_from_below_floor)
        addFlightsFromBelowFloor(cloud_robot, cand, floor, p, params_, result.staircases);
    placeFewLevelSpirals(few_level_spirals, result.staircases);
    addProfileFlights(cloud_robot, cand, floor, p, params_, result.staircases);
    joinSpiralPieces(result.staircases);
    dropSpiralRepeats(result.staircases);
    for (Staircase& s : result.staircases) {
        measureStepExtents(cloud_robot, s);  // widths, sides
        if (const auto turning = turningFlight(s)) {  // a spiral's run at mid radius
            s.step_depth = turning->run_m;
            if (const auto column = columnOf(cloud_robot, s, *turning);
                column && column->radius_m < turning->inner_radius_m)  // inner ends read long
                s.step_depth = runAtMidRadius(*turning, column->radius_m);
            s.slope_rad = std::atan2(s.step_height, s.step_depth);
        }
    }
    // Measured, a second view of one flight shows: two chains through the same nosings seen in
    // pieces (a far VLP-16's, dev2 r0070; a depth camera's scattered ones, dev2 r0031) lie at the
    // same levels, their found edges side by side, but their measured treads overlap.
    mergeOverlappingFlights(result.staircases);
    dropFlightsOutsideTheRises(params_, result.staircases);
    dropRampFlights(cloud_robot, params_, result.staircases);
    dropDescentsFromASlope(cloud_robot, floor, params_, result.staircases);
    dropSecondViews(result.staircases);  // the chains Algorithm 2 left: levels differ (dev3 r0042)
    dropReverseReadings(result.staircases);  // a pit's flight read both ways (dev5 r0284)
    dropFlightsOverTallRisers(cloud_robot, result.staircases);  // bleachers (neg32032 r0850)
    if (debug) debug->accepted = result.staircases;
    return result;
}

}  // namespace stairmap
