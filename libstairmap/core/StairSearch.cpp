#include "core/StairSearch.h"

#include <algorithm>
#include <cmath>

#include "core/LineFusion.h"

namespace stairmap {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kBetweenDz = 0.02;  ///< [m] a blocking line is this far from both edges in z ...

/// Common extent [lo, hi] of two segments along u.
std::pair<double, double> commonExtent(const LineSegment& a, const LineSegment& b,
                                       const Eigen::Vector2d& u) {
    const auto ea = extentAlong(a, u), eb = extentAlong(b, u);
    return {std::max(ea.first, eb.first), std::min(ea.second, eb.second)};
}

/// Index range of lines with z in (z_lo, z_hi).
std::pair<int, int> zRange(const std::vector<LineSegment>& lines, double z_lo, double z_hi) {
    const auto lo = std::upper_bound(lines.begin(), lines.end(), z_lo,
                                     [](double z, const LineSegment& l) { return z < l.z; });
    const auto hi = std::lower_bound(lines.begin(), lines.end(), z_hi,
                                     [](const LineSegment& l, double z) { return l.z < z; });
    return {static_cast<int>(lo - lines.begin()), static_cast<int>(hi - lines.begin())};
}

/// Index range of the lines one rise (condition 1, with the height tolerance) above z.
std::pair<int, int> nextStepRange(const std::vector<LineSegment>& lines, double z,
                                  const DetectorParams& p) {
    const double tol = p.edge_height_tolerance_m + 1e-9;
    return zRange(lines, z + p.min_step_height_m - tol, z + p.max_step_height_m + tol);
}

struct Candidate {
    std::vector<int> steps;
    Eigen::Vector2d normal;
};

/// Algorithm 1, extension: adds, step by step, the next edge that forms a stair with the last one
/// (most overlapping among the valid ones, same direction, nothing in between).
void extend(const std::vector<LineSegment>& lines, const std::vector<char>& used,
            const DetectorParams& p, Candidate& c) {
    for (;;) {
        const int last = c.steps.back();
        const auto [b, e] = nextStepRange(lines, lines[last].z, p);
        int best = -1;
        double best_overlap = 0.0;
        for (int j = b; j < e; ++j) {
            if (used[j] || std::find(c.steps.begin(), c.steps.end(), j) != c.steps.end()) continue;
            const auto pair = checkStairPair(lines[last], lines[j], p);
            if (!pair || pair->normal.dot(c.normal) < std::cos(p.max_parallel_deg * kDegToRad))
                continue;
            if (pair->overlap <= best_overlap || hasLineBetween(lines, last, j, *pair, p)) continue;
            best = j;
            best_overlap = pair->overlap;
        }
        if (best < 0) return;
        c.steps.push_back(best);
        // Follow a turning (spiral) flight: compare the next pair with the latest direction.
        c.normal = checkStairPair(lines[last], lines[best], p)->normal;
    }
}

/// Algorithm 1, initialisation over the lines near the floor; returns the longest staircase.
Candidate bestFromInit(const std::vector<LineSegment>& lines, const std::vector<char>& used,
                       double floor_z, double min_first, const DetectorParams& p) {
    Candidate best;
    const auto [b, e] =
        zRange(lines, floor_z + min_first, floor_z + p.init_height_factor * p.max_step_height_m);
    for (int i = b; i < e; ++i) {
        if (used[i]) continue;
        const auto [jb, je] = nextStepRange(lines, lines[i].z, p);
        for (int j = jb; j < je; ++j) {
            if (used[j]) continue;
            const auto pair = checkStairPair(lines[i], lines[j], p);
            if (!pair || hasLineBetween(lines, i, j, *pair, p)) continue;
            Candidate c{{i, j}, pair->normal};
            extend(lines, used, p, c);
            if (c.steps.size() > best.steps.size()) best = c;
        }
    }
    return best;
}

}  // namespace

std::optional<StairPair> checkStairPair(const LineSegment& lower, const LineSegment& upper,
                                        const DetectorParams& p) {
    StairPair s;
    const double tol = p.edge_height_tolerance_m;  // riser hits read low, see DetectorParams
    s.rise = upper.z - lower.z;  // condition 1
    if (s.rise < p.min_step_height_m - tol || s.rise > p.max_step_height_m + tol) return std::nullopt;
    if (lineAngle(lower, upper) > p.max_parallel_deg * kDegToRad) return std::nullopt;  // cond. 4
    // Normals computed once (LineSegment derives them from theta on every call).
    const Eigen::Vector2d n_low(std::cos(lower.theta), std::sin(lower.theta));
    const Eigen::Vector2d n_up(std::cos(upper.theta), std::sin(upper.theta));
    const double upper_side = n_low.dot(upper.centre()) - lower.rho;  // signed, from lower's line
    // condition 2: mean perpendicular distance of each centre to the other's line
    s.run = 0.5 * (std::abs(n_up.dot(lower.centre()) - upper.rho) + std::abs(upper_side));
    if (s.run < p.min_step_depth_m || s.run > p.max_step_depth_m) return std::nullopt;
    // condition 3, for some rise within the tolerance
    if (std::atan2(s.rise + tol, s.run) / kDegToRad < p.min_slope_deg ||
        std::atan2(std::max(0.0, s.rise - tol), s.run) / kDegToRad > p.max_slope_deg)
        return std::nullopt;
    const Eigen::Vector2d u(-n_low.y(), n_low.x());  // lower.direction()
    const auto [lo, hi] = commonExtent(lower, upper, u);
    s.overlap = hi - lo;
    if (s.overlap < p.min_overlap_ratio * std::min(lower.length(), upper.length()))
        return std::nullopt;
    // Normal from lower to upper: the side of lower's line on which upper lies.
    s.normal = upper_side >= 0 ? n_low : Eigen::Vector2d(-n_low);
    return s;
}

bool hasLineBetween(const std::vector<LineSegment>& lines, int lower, int upper,
                    const StairPair& pair, const DetectorParams& p) {
    const LineSegment& a = lines[lower];
    const LineSegment& b = lines[upper];
    const Eigen::Vector2d u = a.direction();
    const auto [lo, hi] = commonExtent(a, b, u);
    // ... and beyond the height tolerance: an edge read low (a riser hit) has its own tread's
    // points within that tolerance above it, and they are no surface in between.
    const double dz = std::max(kBetweenDz, p.edge_height_tolerance_m);
    const auto [mb, me] = zRange(lines, a.z + dz, b.z - dz);
    const double margin = 0.5 * p.min_step_depth_m;
    for (int m = mb; m < me; ++m) {
        if (m == lower || m == upper) continue;
        const LineSegment& l = lines[m];
        if (lineAngle(l, a) > 2 * p.max_parallel_deg * kDegToRad) continue;
        const auto el = extentAlong(l, u);
        const double cover = std::min(hi, el.second) - std::max(lo, el.first);
        if (cover < p.between_overlap_ratio * (hi - lo)) continue;
        // Position of l across the pair, 0 at the lower edge, run at the upper edge.
        const double t = pair.normal.dot(l.centre() - a.centre());
        const double t_lower = 0.0;
        const double t_upper = pair.normal.dot(b.centre() - a.centre());
        if (t > std::min(t_lower, t_upper) - margin && t < std::max(t_lower, t_upper) + margin)
            return true;
    }
    return false;
}

std::vector<std::vector<int>> searchStaircases(const std::vector<LineSegment>& lines,
                                               double floor_z, double min_first_height,
                                               const DetectorParams& p, std::vector<int>* refused,
                                               std::vector<char>* used_out) {
    std::vector<std::vector<int>> found;
    std::vector<char> used(lines.size(), 0);
    while (static_cast<int>(found.size()) < p.max_staircases_per_direction) {
        const Candidate c = bestFromInit(lines, used, floor_z, min_first_height, p);
        if (static_cast<int>(c.steps.size()) < p.min_steps) {
            if (refused != nullptr && c.steps.size() >= 2) *refused = c.steps;
            break;
        }
        for (int i : c.steps) used[i] = 1;
        found.push_back(c.steps);
    }
    if (used_out != nullptr) *used_out = std::move(used);
    return found;
}

}  // namespace stairmap
