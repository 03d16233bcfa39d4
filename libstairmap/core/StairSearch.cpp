#include "core/StairSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/LineFusion.h"

namespace stairmap {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kBetweenDz = 0.02;  ///< [m] a blocking line is this far from both edges in z ...
/// [m] an edge across one unseen nosing must be twice the chain's rise within this (or the
/// sparse-cloud height tolerance, if larger)
constexpr double kGapRiseTolerance = 0.03;
/// [-] runs are uniform (building codes): a straight chain's next pair whose run per step is more
/// than this factor longer or shorter than the chain's median run is not a step of the same
/// flight (a nosing stepped over reads 2x, a stray line between two nosings 0.5x; 1.5x lies
/// between them)
constexpr double kMaxRunRatio = 1.5;
/// [deg] a pair turned this far from the chain's first pair is on a turning (spiral) flight, whose
/// wedge treads' perpendicular spacing varies: the run ratio is not applied to it
constexpr double kTurningDeg = 20.0;

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

/// [-] at most this many other chains as long as a refused one are returned (refused_ties)
constexpr int kMaxRefusedTies = 8;

struct Candidate {
    std::vector<int> steps;
    Eigen::Vector2d normal;
    double rise = 0.0;  ///< [m] rise per nosing of the latest pair
    Eigen::Vector2d first_normal = Eigen::Vector2d::Zero();  ///< of the lowest pair
    double first_rise = 0.0;                                 ///< [m] of the lowest pair
    /// [m] run per step of every pair taken so far that is not turned (see kTurningDeg),
    /// the initial pair first
    std::vector<double> runs;
    /// [m] heights of the nosings stepped over (pairs two nosings apart), halfway between the pair
    std::vector<double> stepped_over_z;
};

/// Is the pair turned from the chain's first pair, as on a turning (spiral) flight?
bool turned(const StairPair& pair, const Candidate& c) {
    return pair.normal.dot(c.first_normal) < std::cos(kTurningDeg * kDegToRad);
}

/// [m] the chain's run: the median of its straight pairs' runs (the larger middle one for an even
/// count). One wrong pair, the first one included, does not set the run the others must match.
double chainRun(const Candidate& c) {
    thread_local std::vector<double> v;
    v.assign(c.runs.begin(), c.runs.end());
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

/// Records a pair taken into the chain, `steps` nosings apart.
void addRun(const StairPair& pair, int steps, Candidate& c) {
    if (!turned(pair, c)) c.runs.push_back(pair.run / steps);
}

/// Is a pair `steps` nosings apart, with run `pair.run` and turned to `pair.normal`, a step of
/// the chain's flight as far as the run goes (see kMaxRunRatio)?
bool runFitsChain(const StairPair& pair, int steps, const Candidate& c) {
    if (c.runs.empty() || turned(pair, c)) return true;
    const double per_step = pair.run / steps, run = chainRun(c);
    return per_step <= kMaxRunRatio * run && kMaxRunRatio * per_step >= run;
}

/// Definition 1 for a pair of edges `steps` nosings apart (1 = consecutive): rise and run bounds
/// scaled by the number of steps, the chain's own rise within the height tolerance.
std::optional<StairPair> checkStepsApart(const LineSegment& lower, const LineSegment& upper,
                                         int steps, double chain_rise, const DetectorParams& p) {
    if (steps == 1) return checkStairPair(lower, upper, p);
    DetectorParams q = p;
    const double tol = std::max(p.edge_height_tolerance_m, kGapRiseTolerance);
    q.min_step_height_m = steps * chain_rise - tol;
    q.max_step_height_m = steps * chain_rise + tol;
    q.edge_height_tolerance_m = 0.0;
    q.min_step_depth_m = steps * p.min_step_depth_m;
    q.max_step_depth_m = steps * p.max_step_depth_m;
    return checkStairPair(lower, upper, q);
}

/// The next edge `steps` nosings above the chain's last one: the most overlapping valid one (same
/// direction, nothing in between), or -1.
int nextEdge(const std::vector<LineSegment>& lines, const std::vector<char>& used,
             const DetectorParams& p, const Candidate& c, int steps) {
    const int last = c.steps.back();
    const double chain_rise = c.rise;
    const double tol = std::max(p.edge_height_tolerance_m, kGapRiseTolerance) + 1e-9;
    const auto [b, e] =
        steps == 1 ? nextStepRange(lines, lines[last].z, p)
                   : zRange(lines, lines[last].z + steps * chain_rise - tol,
                            lines[last].z + steps * chain_rise + tol);
    int best = -1;
    double best_overlap = 0.0;
    for (int j = b; j < e; ++j) {
        if (used[j] || std::find(c.steps.begin(), c.steps.end(), j) != c.steps.end()) continue;
        const auto pair = checkStepsApart(lines[last], lines[j], steps, chain_rise, p);
        if (!pair || pair->normal.dot(c.normal) < std::cos(p.max_parallel_deg * kDegToRad) ||
            !runFitsChain(*pair, steps, c))
            continue;
        // Across an unseen nosing, what is left of it (a broken or short line) is no obstacle.
        const double expected_z = steps == 1 ? std::numeric_limits<double>::quiet_NaN()
                                             : 0.5 * (lines[last].z + lines[j].z);
        if (pair->overlap <= best_overlap || hasLineBetween(lines, last, j, *pair, p, expected_z))
            continue;
        best = j;
        best_overlap = pair->overlap;
    }
    return best;
}

/// Algorithm 1, extension: adds, step by step, the next edge that forms a stair with the last one.
/// When none does, an edge two nosings higher may continue the chain (one nosing unseen: its
/// line too short or broken in the sparse rows of a far or oblique view); the caller fills the gap.
void extend(const std::vector<LineSegment>& lines, const std::vector<char>& used,
            const DetectorParams& p, Candidate& c) {
    for (;;) {
        const int last = c.steps.back();
        int steps = 1;
        int best = nextEdge(lines, used, p, c, 1);
        if (best < 0) best = nextEdge(lines, used, p, c, steps = 2);
        if (best < 0) return;
        if (steps == 2) c.stepped_over_z.push_back(0.5 * (lines[last].z + lines[best].z));
        // Follow a turning (spiral) flight: compare the next pair with the latest direction.
        const StairPair pair = *checkStepsApart(lines[last], lines[best], steps, c.rise, p);
        addRun(pair, steps, c);
        c.normal = pair.normal;
        c.rise = (lines[best].z - lines[last].z) / steps;
        c.steps.push_back(best);
    }
}

/// The edge `steps` nosings below the chain's first one: the most overlapping valid one, or -1.
int previousEdge(const std::vector<LineSegment>& lines, const std::vector<char>& used,
                 const DetectorParams& p, const Candidate& c, int steps) {
    const int first = c.steps.front();
    const double tol = std::max(p.edge_height_tolerance_m, kGapRiseTolerance) + 1e-9;
    const double z = lines[first].z;
    const auto [b, e] =
        steps == 1 ? zRange(lines, z - p.max_step_height_m - p.edge_height_tolerance_m - 1e-9,
                            z - p.min_step_height_m + p.edge_height_tolerance_m + 1e-9)
                   : zRange(lines, z - steps * c.first_rise - tol, z - steps * c.first_rise + tol);
    int best = -1;
    double best_overlap = 0.0;
    for (int j = b; j < e; ++j) {
        if (used[j] || std::find(c.steps.begin(), c.steps.end(), j) != c.steps.end()) continue;
        const auto pair = checkStepsApart(lines[j], lines[first], steps, c.first_rise, p);
        if (!pair || pair->normal.dot(c.first_normal) < std::cos(p.max_parallel_deg * kDegToRad) ||
            !runFitsChain(*pair, steps, c))
            continue;
        const double expected_z = steps == 1 ? std::numeric_limits<double>::quiet_NaN()
                                             : 0.5 * (lines[j].z + z);
        if (pair->overlap <= best_overlap || hasLineBetween(lines, j, first, *pair, p, expected_z))
            continue;
        best = j;
        best_overlap = pair->overlap;
    }
    return best;
}

/// Algorithm 1 run downwards from the chain's first edge. The initialisation looks near the
/// robot's floor, so a flight rising from a pit or a landing below that floor is found from its
/// part above it; continuing it down to its foot reports the whole flight and where it starts
/// (its nosing at the robot's floor level is a ground line, not searched: stepped over as an
/// unseen nosing, like extend()).
void extendDown(const std::vector<LineSegment>& lines, const std::vector<char>& used,
                const DetectorParams& p, Candidate& c) {
    for (;;) {
        const int first = c.steps.front();
        int steps = 1;
        int best = previousEdge(lines, used, p, c, 1);
        if (best < 0) best = previousEdge(lines, used, p, c, steps = 2);
        if (best < 0) return;
        if (steps == 2) c.stepped_over_z.push_back(0.5 * (lines[first].z + lines[best].z));
        const StairPair pair = *checkStepsApart(lines[best], lines[first], steps, c.first_rise, p);
        addRun(pair, steps, c);
        c.first_normal = pair.normal;
        c.first_rise = (lines[first].z - lines[best].z) / steps;
        c.steps.insert(c.steps.begin(), best);
    }
}

/// Algorithm 1, initialisation over the lines near the floor (first edge from min_first above it):
/// the longest chain from any initial pair whose last edge lies at min_last_z or higher; `ties`
/// (may be null) receives the other chains as long as it, in search order.
Candidate bestFromInit(const std::vector<LineSegment>& lines, const std::vector<char>& used,
                       double floor_z, double min_first, const DetectorParams& p,
                       std::vector<Candidate>* ties,
                       double min_last_z = -std::numeric_limits<double>::infinity()) {
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
            Candidate c{{i, j},     pair->normal, pair->rise, pair->normal,
                        pair->rise, {pair->run},  {}};
            extend(lines, used, p, c);
            if (lines[c.steps.back()].z < min_last_z) continue;
            if (c.steps.size() > best.steps.size()) {
                best = c;
                if (ties) ties->clear();
            } else if (ties && c.steps.size() == best.steps.size() &&
                       static_cast<int>(c.steps.size()) < p.min_steps && c.steps != best.steps) {
                // Only a refused chain's rivals are ever used: no copies for accepted lengths.
                ties->push_back(c);
            }
        }
    }
    return best;
}

/// The nosings at the floor's height a chain stepped over: ground rows are not searched, so the
/// nosing there of a flight rising from below the floor is never a line (kGapRiseTolerance: the
/// stepped-over nosing lies halfway between its neighbours, each read a few cm off).
int floorNosingsSteppedOver(const Candidate& c, double floor_z, const DetectorParams& p) {
    return static_cast<int>(
        std::count_if(c.stepped_over_z.begin(), c.stepped_over_z.end(), [&](double z) {
            return std::abs(z - floor_z) <= p.floor_tolerance_m + kGapRiseTolerance;
        }));
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
                    const StairPair& pair, const DetectorParams& p, double expected_z) {
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
        if (std::abs(l.z - expected_z) < dz) continue;  // false for NaN
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
                                               std::vector<char>* used_out, bool continue_down,
                                               std::vector<std::vector<int>>* refused_ties) {
    std::vector<std::vector<int>> found;
    std::vector<char> used(lines.size(), 0);
    std::vector<Candidate> ties;
    while (static_cast<int>(found.size()) < p.max_staircases_per_direction) {
        ties.clear();
        Candidate c = bestFromInit(lines, used, floor_z, min_first_height, p,
                                   refused_ties ? &ties : nullptr);
        if (continue_down && c.steps.size() >= 2) extendDown(lines, used, p, c);
        // Flights rising from below the floor (DetectorParams::ascend_from_below_floor): their
        // nosing at the floor's height counts; and where the chains from the floor fall short
        // before any flight is found, a chain from the lines below it that rises above it.
        const bool from_below = continue_down && p.ascend_from_below_floor;
        const auto length = [&](const Candidate& k) {
            return static_cast<int>(k.steps.size()) +
                   (from_below ? floorNosingsSteppedOver(k, floor_z, p) : 0);
        };
        if (from_below && found.empty() && length(c) < p.min_steps) {
            Candidate below =
                bestFromInit(lines, used, floor_z, -p.init_height_factor * p.max_step_height_m, p,
                             nullptr, floor_z + p.floor_tolerance_m);
            if (below.steps.size() >= 2) extendDown(lines, used, p, below);
            if (length(below) >= p.min_steps) c = std::move(below);
        }
        if (length(c) < p.min_steps) {
            if (refused != nullptr && c.steps.size() >= 2) *refused = c.steps;
            if (refused_ties != nullptr && c.steps.size() >= 2) {
                for (Candidate& t : ties) {
                    if (static_cast<int>(refused_ties->size()) >= kMaxRefusedTies) break;
                    if (continue_down) extendDown(lines, used, p, t);
                    if (t.steps.size() == c.steps.size() && t.steps != c.steps)
                        refused_ties->push_back(t.steps);
                }
            }
            break;
        }
        for (int i : c.steps) used[i] = 1;
        found.push_back(c.steps);
    }
    if (used_out != nullptr) *used_out = std::move(used);
    return found;
}

}  // namespace stairmap
