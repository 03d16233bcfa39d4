#include "core/OverlappingFlights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/MergeParams.h"
#include "core/StairEdgeFusion.h"
#include "core/StaircaseGeometry.h"
#include "core/StaircaseMerge.h"

namespace stairmap {
namespace {

/// Definition 2 without the overlap gate: collinear pieces of one nosing at any lateral gap.
MergeParams anyGap() {
    MergeParams m;
    m.min_edge_overlap_m = -4.9;
    return m;
}

/// Index of a's step nearest in height to z within tol, or -1.
int levelOf(const Staircase& a, double z, double tol) {
    int best = -1;
    for (std::size_t k = 0; k < a.steps.size(); ++k) {
        const double dz = std::abs(a.steps[k].centre().z() - z);
        if (dz <= tol) {
            best = static_cast<int>(k);
            tol = dz;
        }
    }
    return best;
}

double levelTolerance(const Staircase& a, const OverlappingFlightParams& p) {
    return std::max(p.min_height_tolerance_m, a.step_height / 3.0);
}

/// Is edge e on the tread of a's step k (within its run, along the nosing and its neighbours)?
bool onTread(const Staircase& a, std::size_t k, const StairEdge& e,
             const OverlappingFlightParams& p) {
    const Eigen::Vector2d c = e.centre().head<2>(), ck = a.steps[k].centre().head<2>();
    const Eigen::Vector2d n = outwardNormal(a, k), u(-n.y(), n.x());
    const double run = std::max(a.step_depth, 0.05);
    const double s = n.dot(c - ck);
    const bool up = a.direction == StairDirection::Ascending;
    // Ascending: the tread of a nosing lies beyond it; descending: towards the observer.
    const double lo = up ? -p.before_nosing_runs * run : -run;
    const double hi = up ? run : p.before_nosing_runs * run;
    if (s < lo || s > hi) return false;
    double tmin = std::numeric_limits<double>::infinity(), tmax = -tmin;
    for (std::size_t j = (k > 0 ? k - 1 : 0); j <= std::min(k + 1, a.steps.size() - 1); ++j) {
        for (const Eigen::Vector3d& q : {a.steps[j].start, a.steps[j].end}) {
            const double t = u.dot(q.head<2>() - ck);
            tmin = std::min(tmin, t);
            tmax = std::max(tmax, t);
        }
    }
    const double t = u.dot(c - ck);
    return t >= tmin - p.lateral_margin_m && t <= tmax + p.lateral_margin_m;
}

/// Levels both staircases have (within half a rise), and how many of them are the same stair.
std::pair<int, int> sharedLevels(const Staircase& a, const Staircase& b, const MergeParams& m) {
    const double half_rise = 0.5 * std::max(a.step_height, 0.05);
    int paired = 0, same = 0;
    for (const StairEdge& e : b.steps) {
        const int k = levelOf(a, e.centre().z(), half_rise);
        if (k < 0) continue;
        ++paired;
        if (isSameStairEdge(a.steps[static_cast<std::size_t>(k)], e, m)) ++same;
    }
    return {paired, same};
}

/// Rule 1: split halves (Algorithm 2 proper).
std::optional<Staircase> mergeSplitHalves(const Staircase& a, const Staircase& b,
                                          const OverlappingFlightParams& p) {
    MergeParams near;
    near.min_edge_overlap_m = -p.split_max_gap_m;
    if (auto merged = mergeStaircases(a, b, near)) return merged;
    const MergeParams wide = anyGap();
    const auto [paired, same] = sharedLevels(a, b, wide);
    if (same >= 2 && 2 * same >= paired) return mergeStaircases(a, b, wide);
    return std::nullopt;
}

bool isSecondView(const Staircase& a, const Staircase& b, const OverlappingFlightParams& p) {
    const auto enough = [&](int on, std::size_t n) {
        return on >= 2 && on >= p.min_on_tread_fraction * static_cast<double>(n);
    };
    return enough(edgesOnTreads(a, b, p), b.steps.size()) ||
           enough(edgesOnTreads(b, a, p), a.steps.size());
}

/// Rule 2: keeps `keep`, fuses the edges of `drop` that are the same stair as keep's edge at
/// their level (merge(l_i, l_j)), suppresses the rest.
void absorb(Staircase& keep, const Staircase& drop, const OverlappingFlightParams& p) {
    const MergeParams wide = anyGap();
    const double tol = levelTolerance(keep, p);
    for (const StairEdge& e : drop.steps) {
        const int k = levelOf(keep, e.centre().z(), tol);
        if (k < 0) continue;
        StairEdge& mine = keep.steps[static_cast<std::size_t>(k)];
        if (onTread(keep, static_cast<std::size_t>(k), e, p) && isSameStairEdge(mine, e, wide))
            mine = fuseEdges(mine, 1, e, 1, keep.heading_rad, wide);
    }
    estimateGeometry(keep);
}

/// Rule 3: keeps `keep`, its edges at the levels `half` also has lengthened along themselves over
/// the other half's edge (never shortened); the rest of `half` is suppressed.
void widenOver(Staircase& keep, const Staircase& half, const OverlappingFlightParams& p) {
    for (const StairEdge& e : half.steps) {
        const int k = levelOf(keep, e.centre().z(), p.min_height_tolerance_m);
        if (k < 0) continue;
        StairEdge& mine = keep.steps[static_cast<std::size_t>(k)];
        const Eigen::Vector3d c = mine.centre();
        Eigen::Vector3d u = mine.end - mine.start;
        u.z() = 0.0;
        if (u.norm() < 1e-9) continue;
        u.normalize();
        double lo = u.dot(mine.start - c), hi = u.dot(mine.end - c);
        for (const Eigen::Vector3d& q : {e.start, e.end}) {
            lo = std::min(lo, u.dot(q - c));
            hi = std::max(hi, u.dot(q - c));
        }
        mine.start = c + lo * u;
        mine.end = c + hi * u;
    }
    estimateGeometry(keep);
}

double totalLength(const Staircase& s) {
    double sum = 0.0;
    for (const StairEdge& e : s.steps) sum += e.length();
    return sum;
}

/// Does `a` win over `b` (Algorithm 1 keeps the longest chain; ties: the longer edges)?
bool stronger(const Staircase& a, const Staircase& b) {
    if (a.steps.size() != b.steps.size()) return a.steps.size() > b.steps.size();
    return totalLength(a) >= totalLength(b);
}

/// One merge or suppression between two staircases of `found`; false when none applies.
bool mergeOnePair(std::vector<Staircase>& found, const OverlappingFlightParams& p) {
    for (std::size_t i = 0; i < found.size(); ++i) {
        for (std::size_t j = i + 1; j < found.size(); ++j) {
            if (found[i].direction != found[j].direction) continue;
            if (auto merged = mergeSplitHalves(found[i], found[j], p)) {
                found[i] = std::move(*merged);
            } else if (isSecondView(found[i], found[j], p)) {
                if (!stronger(found[i], found[j])) std::swap(found[i], found[j]);
                absorb(found[i], found[j], p);
            } else if (sideBySideHalves(found[i], found[j], p)) {
                if (!stronger(found[i], found[j])) std::swap(found[i], found[j]);
                widenOver(found[i], found[j], p);
            } else {
                continue;
            }
            found.erase(found.begin() + static_cast<std::ptrdiff_t>(j));
            return true;
        }
    }
    return false;
}

}  // namespace

int edgesOnTreads(const Staircase& a, const Staircase& b, const OverlappingFlightParams& p) {
    if (a.steps.empty()) return 0;
    const double tol = levelTolerance(a, p);
    int on = 0;
    for (const StairEdge& e : b.steps) {
        const int k = levelOf(a, e.centre().z(), tol);
        if (k >= 0 && onTread(a, static_cast<std::size_t>(k), e, p)) ++on;
    }
    return on;
}

bool sideBySideHalves(const Staircase& a, const Staircase& b, const OverlappingFlightParams& p) {
    if (a.direction != b.direction || a.steps.empty() || b.steps.empty()) return false;
    const Eigen::Vector2d ha(std::cos(a.heading_rad), std::sin(a.heading_rad));
    const Eigen::Vector2d hb(std::cos(b.heading_rad), std::sin(b.heading_rad));
    if (ha.dot(hb) < std::cos(p.side_max_heading_diff_deg * M_PI / 180.0)) return false;
    const Eigen::Vector2d n = (ha + hb).normalized(), u(-n.y(), n.x());
    // The flights' lateral extents must meet or leave a gap narrower than the limit.
    const auto [alo, ahi] = lateralExtent(a, u);
    const auto [blo, bhi] = lateralExtent(b, u);
    if (std::max(blo - ahi, alo - bhi) > p.side_max_lateral_gap_m) return false;
    const double along_tol = std::max(p.side_along_tolerance_m, 0.15 * std::min(a.step_depth, b.step_depth));
    int shared = 0;
    for (const StairEdge& e : b.steps) {
        const int k = levelOf(a, e.centre().z(), p.min_height_tolerance_m);
        if (k < 0) continue;
        const Eigen::Vector3d d = e.centre() - a.steps[static_cast<std::size_t>(k)].centre();
        if (std::abs(n.dot(d.head<2>())) > along_tol) return false;  // every shared level agrees
        ++shared;
    }
    return shared >= p.side_min_shared_levels;
}

int mergeOverlappingFlights(std::vector<Staircase>& found, const OverlappingFlightParams& params) {
    int removed = 0;
    while (mergeOnePair(found, params)) ++removed;
    return removed;
}

}  // namespace stairmap
