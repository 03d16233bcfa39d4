#include "core/MissingNosings.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/StaircaseGeometry.h"
#include "core/UpperMedian.h"

namespace stairmap {
namespace {

constexpr double kMinGapRatio = 1.6;  ///< [-] a pair this many median rises apart has a gap ...
constexpr double kMaxGapRatio = 2.4;  ///< [-] ... up to this many
/// [m^2, rad^2] variances of an unseen edge's (rho, theta): it is a guess, worth little in merges
constexpr double kUnseenRhoVar = 0.05 * 0.05;
constexpr double kUnseenThetaVar = 0.1 * 0.1;

/// [-] a pair within these multiples of the one-step rise and spacing is one step apart
constexpr double kOneStepMin = 0.75;
constexpr double kOneStepMax = 1.33;

/// [m] The pair's horizontal spacing: the mean of each centre's XY distance to the other's line.
/// From one line alone, a short piece turned 30 deg off its nosing (a far ring's few points)
/// puts the other centre a third of a run off (dev6 r0026: 0.398 m from the turned piece's line,
/// 0.228 m the other way, their mean 0.313 m, on 0.303 m runs).
double spacing(const LineSegment& a, const LineSegment& b) {
    return 0.5 * (std::abs(a.distanceTo(b.centre())) + std::abs(b.distanceTo(a.centre())));
}

/// [m] a pair of edges this long pins its spacing better than riser hits pin their heights
constexpr double kLongEdgeM = 1.0;
bool oneStep(double ratio) { return ratio >= kOneStepMin && ratio <= kOneStepMax; }
bool twoSteps(double ratio) { return ratio >= kMinGapRatio && ratio <= kMaxGapRatio; }

/// The rise of one step when most of the chain's pairs are two steps apart: a sparse far view
/// whose rings alias with the steps may give every other nosing, with one-step pairs between
/// (dev2 r0223: 1, 2, 1, 2, 2 steps; the median then reads the two-step rise and nothing is put
/// back). The pairs under 1/kMinGapRatio of the median rise are taken as one step, and the unit
/// is kept only when every pair is one or two of its steps apart in both rise and horizontal
/// spacing: raw heights of riser hits read low by up to a ring spacing, so a rise alone could make
/// an ordinary pair look like two steps. For the same reason a pair one run apart is one step
/// while its rise is under two steps' lower bound (dev r0192: 1.4 steps from a low riser hit).
/// `rises` and `runs` (horizontal spacings) are the consecutive pairs'. Returns 0 when the chain
/// is not so.
double oneStepRiseOfAliasedChain(const std::vector<double>& rises, const std::vector<double>& runs,
                                 double median_rise, double& one_step_run) {
    std::vector<double> small_rises, small_runs;
    for (std::size_t i = 0; i < rises.size(); ++i) {
        if (rises[i] * kMinGapRatio > median_rise) continue;
        small_rises.push_back(rises[i]);
        small_runs.push_back(runs[i]);
    }
    if (small_rises.empty()) return 0.0;
    const double unit_rise = upperMedian(small_rises), unit_run = upperMedian(small_runs);
    if (unit_rise <= 0.0 || unit_run <= 0.0) return 0.0;
    for (std::size_t i = 0; i < rises.size(); ++i) {
        const double kz = rises[i] / unit_rise, ks = runs[i] / unit_run;
        const bool one = oneStep(ks) && kz >= kOneStepMin && kz < kMinGapRatio;
        if (!one && !(twoSteps(kz) && twoSteps(ks))) return 0.0;
    }
    one_step_run = unit_run;
    return unit_rise;
}

/// Whether one of `lines` lies where the nosing halfway between edges a and b would (within a
/// quarter of their spacing of its line and of their rise of its height, beside its extent): then
/// the pair is not two steps with the middle nosing unseen, whatever kept the search off it.
bool seenBetween(const std::vector<LineSegment>& lines, const LineSegment& a,
                 const LineSegment& b) {
    const LineSegment mid = halfwayNosing(a, b);
    const double apart = spacing(a, b), rise = std::abs(b.z - a.z);
    const Eigen::Vector2d u = mid.direction();
    for (const LineSegment& l : lines) {
        if (std::abs(l.z - mid.z) > 0.25 * rise) continue;
        if (std::abs(mid.distanceTo(l.centre())) > 0.25 * apart) continue;
        if (std::abs(u.dot(l.centre() - mid.centre())) <= 0.5 * (mid.length() + l.length()))
            return true;
    }
    return false;
}

/// b's end points in the order of a's (start first): put-back nosings pair them up.
std::pair<Eigen::Vector2d, Eigen::Vector2d> endsAlong(const LineSegment& a, const LineSegment& b) {
    if (a.direction().dot(b.end - b.start) >= 0) return {b.start, b.end};
    return {b.end, b.start};
}

/// [m] positions of the edges across them: cumulative spacings from the first.
std::vector<double> positionsAcross(const std::vector<LineSegment>& edges) {
    std::vector<double> at(edges.size(), 0.0);
    for (std::size_t i = 1; i < edges.size(); ++i)
        at[i] = at[i - 1] + spacing(edges[i - 1], edges[i]);
    return at;
}

/// The levels (from 0) of positions `at` on the widest comb of one run in [min_run, max_run]
/// that holds each within xy_tolerance_m, every pair 1-3 runs apart; empty when none does.
std::vector<double> combLevels(const std::vector<double>& at, const SpacingLevelParams& p) {
    std::vector<double> best;
    double best_run = 0;
    for (std::size_t j = 1; j < at.size(); ++j)
        for (int m = 1; m <= 3; ++m) {
            const double run = (at[j] - at[j - 1]) / m;
            if (run < p.min_run_m || run > p.max_run_m || run <= best_run) continue;
            std::vector<double> k(at.size());
            bool rising = true;
            std::size_t one_run_pairs = 0;
            for (std::size_t i = 0; i < at.size(); ++i) {
                k[i] = std::round(at[i] / run);
                if (i == 0) continue;
                if (k[i] - k[i - 1] < 1 || k[i] - k[i - 1] > 3) rising = false;
                one_run_pairs += k[i] - k[i - 1] == 1;
            }
            // The run is the step most pairs show: a comb of half the run holds any chain.
            if (!rising || 2 * one_run_pairs < at.size() - 1 ||
                lineFitError(k, at, nullptr) > p.xy_tolerance_m)
                continue;
            best = std::move(k);
            best_run = run;
        }
    return best;
}

}  // namespace

int fillNosingsBySpacing(std::vector<LineSegment>& edges, const SpacingLevelParams& p) {
    if (static_cast<int>(edges.size()) < p.min_edges) return 0;
    for (const LineSegment& e : edges)
        if (e.num_points == 0) return 0;  // seen edges only: put-back ones mark the height levels
    const Eigen::Vector2d first = edges.front().direction();
    const double min_cos = std::cos(p.max_turn_deg * M_PI / 180.0);
    for (const LineSegment& e : edges)
        if (std::abs(first.dot(e.direction())) < min_cos) return 0;
    const std::vector<double> at = positionsAcross(edges);
    const std::vector<double> comb = combLevels(at, p);
    if (comb.empty() || comb.back() == static_cast<double>(edges.size() - 1)) return 0;
    // The heights' own levels: the chain as fillMissingNosings would put its gaps back.
    std::vector<LineSegment> by_height = edges;
    fillMissingNosings(by_height, p.height_min_rise_m);
    std::vector<double> height_levels;
    for (std::size_t i = 0; i < by_height.size(); ++i)
        if (by_height[i].num_points > 0) height_levels.push_back(static_cast<double>(i));
    if (height_levels.size() != edges.size() ||
        lineFitError(height_levels, at, nullptr) <= p.min_height_levels_error_m)
        return 0;
    for (std::size_t i = 1; i < edges.size(); ++i)
        if (comb[i] - comb[i - 1] != height_levels[i] - height_levels[i - 1] &&
            std::max(edges[i - 1].z, edges[i].z) <= p.riser_hits_above_z_m)
            return 0;  // the levels differ where the heights are seen from above
    std::vector<double> z;
    for (const LineSegment& e : edges) z.push_back(e.z);
    double rise = 0;
    if (lineFitError(comb, z, &rise) > p.height_tolerance_m || std::abs(rise) < p.min_rise_m ||
        std::abs(rise) > p.max_rise_m)
        return 0;
    std::vector<LineSegment> all;
    int put_back = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (i > 0) {
            const int gap = static_cast<int>(comb[i] - comb[i - 1]);
            const LineSegment& a = edges[i - 1];
            const auto [b_start, b_end] = endsAlong(a, edges[i]);
            const double b_z = edges[i].z;
            for (int g = 1; g < gap; ++g, ++put_back) {
                const double t = static_cast<double>(g) / gap;
                all.push_back(unseenNosing((1 - t) * a.start + t * b_start,
                                           (1 - t) * a.end + t * b_end, (1 - t) * a.z + t * b_z));
            }
        }
        all.push_back(edges[i]);
    }
    edges = std::move(all);
    return put_back;
}

LineSegment unseenNosing(const Eigen::Vector2d& start, const Eigen::Vector2d& end, double z) {
    LineSegment m;
    m.start = start;
    m.end = end;
    m.z = z;
    const Eigen::Vector2d d = (end - start).normalized();
    Eigen::Vector2d n(d.y(), -d.x());
    if (n.dot(m.start) < 0) n = -n;  // Hessian form: rho >= 0
    m.rho = n.dot(m.start);
    m.theta = std::atan2(n.y(), n.x());
    m.cov << kUnseenRhoVar, 0.0, 0.0, kUnseenThetaVar;
    m.num_points = 0;
    return m;
}

LineSegment halfwayNosing(const LineSegment& a, const LineSegment& b) {
    const auto [b_start, b_end] = endsAlong(a, b);
    return unseenNosing(0.5 * (a.start + b_start), 0.5 * (a.end + b_end), 0.5 * (a.z + b.z));
}

int fillMissingNosings(std::vector<LineSegment>& edges, double min_rise_m) {
    if (edges.size() < 3) return 0;
    std::vector<double> rises, runs;
    for (std::size_t i = 1; i < edges.size(); ++i) {
        rises.push_back(std::abs(edges[i].z - edges[i - 1].z));
        runs.push_back(spacing(edges[i - 1], edges[i]));
    }
    const double median_rise = upperMedian(rises);
    double run = upperMedian(runs);
    const double aliased_unit = oneStepRiseOfAliasedChain(rises, runs, median_rise, run);
    const double rise = aliased_unit > 0.0 ? aliased_unit : median_rise;
    if (rise <= 0.0) return 0;
    int inserted = 0;
    for (std::size_t i = 1; i < edges.size(); ++i) {
        const double ratio = std::abs(edges[i].z - edges[i - 1].z) / rise;
        if (ratio < kMinGapRatio || ratio > kMaxGapRatio) continue;
        const bool long_pair = std::min(edges[i - 1].length(), edges[i].length()) >= kLongEdgeM;
        if ((median_rise < min_rise_m || long_pair) &&
            oneStep(spacing(edges[i - 1], edges[i]) / run))
            continue;
        edges.insert(edges.begin() + static_cast<std::ptrdiff_t>(i),
                     halfwayNosing(edges[i - 1], edges[i]));
        ++inserted;
        ++i;  // skip the inserted edge
    }
    return inserted;
}

bool putBackEveryOtherNosing(const std::vector<LineSegment>& lines,
                             std::vector<LineSegment>& edges) {
    std::vector<LineSegment> all;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        if (k > 0) {
            if (seenBetween(lines, edges[k - 1], edges[k])) return false;
            all.push_back(halfwayNosing(edges[k - 1], edges[k]));
        }
        all.push_back(edges[k]);
    }
    edges = std::move(all);
    return true;
}

}  // namespace stairmap
