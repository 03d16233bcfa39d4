#include "core/TreadSpirals.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/HeightGrid.h"
#include "core/TreadBoundaries.h"

namespace stairmap {

namespace {

/// [m] a nosing's two tread patches may differ by this much more or less than a rise: a patch's
/// height is the mean of its cells' highest points, which a depth camera's noise lifts
constexpr double kTreadRiseNoise = 0.03;
/// [-] seen levels enough for a spiral with tread nosings among its lines: four flat wedges a rise
/// apart turning about one axis (the row lines alone need five, SpiralSearchParams)
constexpr int kSeenLevels = 4;
/// [m] the surface's cells start this far below the floor (its band, TreadBoundaryParams)
constexpr double kBelowFloor = 0.05;
/// [-] seen levels of a spiral that must be tread nosings: with one, the others are the row lines
/// the first search already found no spiral in, and a level LiDAR's ring heights on the risers
/// made a helix of twice the rise through one true tread nosing (check9 r0147, 12 cm off; seen
/// after scoring the untuned sets, which then lost two more readings 11 cm and 87 cm off; dev
/// lost one spiral read well, dev4 r0111)
constexpr int kTreadLevels = 2;
/// [m] a seen level lies on a tread nosing this close to its height
constexpr double kSameHeight = 0.01;

/// Seen levels of spiral `f` at the height of one of the first `tread_count` lines (the tread
/// nosings) whose line passes by its axis (SpiralSearchParams::extra_max_axis_offset_m).
int levelsOnTreadNosings(const SpiralFlight& f, const std::vector<LineSegment>& lines,
                         int tread_count, const SpiralSearchParams& search) {
    int levels = 0;
    for (const LineSegment& e : f.edges) {
        if (e.num_points == 0) continue;  // put back
        levels +=
            std::any_of(lines.begin(), lines.begin() + tread_count, [&](const LineSegment& l) {
                return std::abs(l.z - e.z) < kSameHeight &&
                       std::abs(l.distanceTo(f.axis)) < search.extra_max_axis_offset_m;
            });
    }
    return levels;
}

}  // namespace

std::vector<SpiralFlight> findTreadSpirals(const PointCloud& cloud, const Eigen::Vector2d& axis,
                                           const std::vector<LineSegment>& front_drops,
                                           const std::vector<LineSegment>& back_drops,
                                           const SpiralSearchParams& search,
                                           const TreadSpiralParams& params) {
    thread_local HeightGrid surface;  // scratch re-used between calls
    surface.fill(cloud, axis, params.window_m, params.cell_m, search.floor_z - kBelowFloor,
                 search.floor_z + params.max_height_above_floor_m);
    TreadBoundaryParams tb;
    tb.floor_z = search.floor_z;
    tb.min_rise_m = search.min_rise_m - kTreadRiseNoise;
    tb.max_rise_m = search.max_rise_m + kTreadRiseNoise;
    std::vector<LineSegment> lines = treadBoundaryNosings(surface, tb);
    if (lines.empty()) return {};
    SpiralSearchParams sp = search;
    sp.min_seen_levels = kSeenLevels;
    sp.pair_lines = static_cast<int>(lines.size());  // the tread nosings, first in `lines`
    sp.rim_search = false;  // the first search looked for rims
    // The row lines with an end within the window: no other can be a wedge nosing about an axis
    // there (the search's pairs grow with the square of the lines, its inliers with them).
    const auto nearAxis = [&](const LineSegment& l) {
        return std::min((l.start - axis).norm(), (l.end - axis).norm()) <= params.window_m;
    };
    std::copy_if(front_drops.begin(), front_drops.end(), std::back_inserter(lines), nearAxis);
    std::vector<LineSegment> backs;
    std::copy_if(back_drops.begin(), back_drops.end(), std::back_inserter(backs), nearAxis);
    std::vector<SpiralFlight> found;
    for (SpiralFlight& f : findSpirals(lines, backs, sp))
        if (levelsOnTreadNosings(f, lines, sp.pair_lines, sp) >= kTreadLevels)
            found.push_back(std::move(f));
    return found;
}

}  // namespace stairmap
