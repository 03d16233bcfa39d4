#include "fleet/StaircasePairing.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/StaircaseTransform.h"

namespace stairmap::fleet {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kDefaultRise = 0.15;  // [m] for flights without a rise estimate (one step)

double riseOf(const Staircase& s) { return s.step_height > 0.01 ? s.step_height : kDefaultRise; }

double minZ(const Staircase& s) {
    double z = s.steps.front().start.z();
    for (const StairEdge& e : s.steps) z = std::min(z, e.centre().z());
    return z;
}

double maxZ(const Staircase& s) {
    double z = s.steps.front().start.z();
    for (const StairEdge& e : s.steps) z = std::max(z, e.centre().z());
    return z;
}

/// Level of the lowest seen nosing above the floor the flight leaves from (1 = first nosing).
int bottomOffset(const FlightView& v) {
    if (!std::isfinite(v.bottom_floor_z)) return 1;
    const int level =
        static_cast<int>(std::lround((minZ(v.stairs) - v.bottom_floor_z) / riseOf(v.stairs)));
    return std::max(1, level);
}

bool within(double a, double b, double abs_tol, double rel_tol) {
    return std::abs(a - b) <= std::max(abs_tol, rel_tol * std::max(std::abs(a), std::abs(b)));
}

Eigen::Vector2d direction(const StairEdge& e) {
    const Eigen::Vector2d d = (e.end - e.start).head<2>();
    return d.norm() > 1e-9 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d::UnitX();
}

/// Matching cost of two edges in one frame, or a negative value when they are not one stair.
double edgeMatchCost(const StairEdge& a, const StairEdge& b, const AlignmentParams& p) {
    const double dz = std::abs(a.centre().z() - b.centre().z());
    const Eigen::Vector2d da = direction(a), db = direction(b);
    const double angle = std::acos(std::clamp(da.dot(db), -1.0, 1.0));
    if (dz > p.match_height_m || angle > p.match_angle_deg * kDegToRad) return -1.0;
    const Eigen::Vector2d na(-da.y(), da.x()), nb(-db.y(), db.x());
    const Eigen::Vector2d ca = a.centre().head<2>(), cb = b.centre().head<2>();
    const double dist = 0.5 * (std::abs(na.dot(cb - ca)) + std::abs(nb.dot(ca - cb)));
    if (dist > p.match_distance_m) return -1.0;
    // The two extents along a's direction must overlap (side-by-side flights stay apart).
    const double a0 = 0.0, a1 = da.dot((a.end - a.start).head<2>());
    const double b0 = da.dot((b.start - a.start).head<2>()), b1 = da.dot((b.end - a.start).head<2>());
    if (std::min(a1, std::max(b0, b1)) <= std::max(a0, std::min(b0, b1))) return -1.0;
    return dz / p.match_height_m + dist / p.match_distance_m;
}

}  // namespace

std::vector<FlightView> flightViews(const LandmarkMapState& state) {
    std::vector<FlightView> views;
    for (const StaircaseLandmark& lm : state.staircases) {
        if (lm.stairs.steps.empty()) continue;
        FlightView v;
        v.id = lm.id;
        v.stairs = lm.stairs;
        v.bottom_observed = lm.bottom_observed;
        v.top_observed = lm.top_observed;
        for (const Floor& f : state.floor_levels) {
            if (f.id == lm.bottom_floor) v.bottom_floor_z = f.z;
        }
        views.push_back(std::move(v));
    }
    return views;
}

FlightView transformFlight(const FlightView& view, const Transform4& T_to_from) {
    FlightView out = view;
    out.stairs = transformStaircase(view.stairs, T_to_from.isometry());
    out.bottom_floor_z = view.bottom_floor_z + T_to_from.z;
    return out;
}

double meanTurnPerStep(const Staircase& stairs) {
    if (stairs.steps.size() < 2) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 1; i < stairs.steps.size(); ++i) {
        const Eigen::Vector2d d0 = direction(stairs.steps[i - 1]), d1 = direction(stairs.steps[i]);
        sum += std::atan2(d0.x() * d1.y() - d0.y() * d1.x(), d0.dot(d1));
    }
    return sum / static_cast<double>(stairs.steps.size() - 1);
}

bool shapesAgree(const Staircase& a, const Staircase& b, const AlignmentParams& p) {
    return within(a.step_height, b.step_height, p.rise_tolerance_m, 0.05) &&
           within(a.step_depth, b.step_depth, p.run_tolerance_m, 0.10) &&
           within(a.step_width, b.step_width, p.width_tolerance_m, 0.0) &&
           std::abs(meanTurnPerStep(a) - meanTurnPerStep(b)) <= p.turn_tolerance_deg * kDegToRad;
}

std::vector<int> stepLevels(const Staircase& stairs) {
    std::vector<int> levels;
    if (stairs.steps.empty()) return levels;
    const double z0 = minZ(stairs), rise = riseOf(stairs);
    for (const StairEdge& e : stairs.steps) {
        levels.push_back(static_cast<int>(std::lround((e.centre().z() - z0) / rise)));
    }
    return levels;
}

std::vector<StepPair> stepPairsAtShift(const Staircase& first, const Staircase& other, int shift) {
    const std::vector<int> la = stepLevels(first), lb = stepLevels(other);
    std::vector<StepPair> pairs;
    std::set<int> used;
    for (std::size_t j = 0; j < lb.size(); ++j) {
        for (std::size_t i = 0; i < la.size(); ++i) {
            if (la[i] != lb[j] + shift || used.count(static_cast<int>(i))) continue;
            pairs.push_back({static_cast<int>(i), static_cast<int>(j)});
            used.insert(static_cast<int>(i));
            break;
        }
    }
    return pairs;
}

std::vector<int> candidateShifts(const FlightView& a, const FlightView& b, const AlignmentParams& p) {
    const std::vector<int> la = stepLevels(a.stairs), lb = stepLevels(b.stairs);
    const int top_a = *std::max_element(la.begin(), la.end());
    const int top_b = *std::max_element(lb.begin(), lb.end());
    const int off_a = bottomOffset(a), off_b = bottomOffset(b);
    int lo = -top_b, hi = top_a;
    if (a.bottom_observed && b.bottom_observed) {
        lo = hi = off_b - off_a;  // both saw the floor the flight leaves from
    } else if (a.top_observed && b.top_observed) {
        lo = hi = top_a - top_b;  // both saw the top nosing, flush with the upper floor
    } else {
        if (a.top_observed) hi = std::min(hi, top_a - top_b);
        if (b.top_observed) lo = std::max(lo, top_a - top_b);
        if (a.bottom_observed) lo = std::max(lo, 1 - off_a);
        if (b.bottom_observed) hi = std::min(hi, off_b - 1);
    }
    std::vector<int> shifts;
    for (int k = lo; k <= hi; ++k) {
        if (static_cast<int>(stepPairsAtShift(a.stairs, b.stairs, k).size()) >= p.min_overlap_steps)
            shifts.push_back(k);
    }
    return shifts;
}

std::vector<StepPair> coincidingSteps(const Staircase& first, const Staircase& other_in_first,
                                      const AlignmentParams& p) {
    struct Candidate {
        double cost;
        StepPair pair;
    };
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < first.steps.size(); ++i) {
        for (std::size_t j = 0; j < other_in_first.steps.size(); ++j) {
            const double cost = edgeMatchCost(first.steps[i], other_in_first.steps[j], p);
            if (cost >= 0) candidates.push_back({cost, {static_cast<int>(i), static_cast<int>(j)}});
        }
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; });
    std::vector<StepPair> pairs;
    std::set<int> used_a, used_b;
    for (const Candidate& c : candidates) {
        if (used_a.count(c.pair.first) || used_b.count(c.pair.other)) continue;
        used_a.insert(c.pair.first);
        used_b.insert(c.pair.other);
        pairs.push_back(c.pair);
    }
    return pairs;
}

bool endsConsistent(const FlightView& a, const FlightView& b, const AlignmentParams& p) {
    (void)p;
    const double slack = 0.5 * riseOf(a.stairs);
    auto bottomFloor = [](const FlightView& v) {
        return std::isfinite(v.bottom_floor_z) ? v.bottom_floor_z : minZ(v.stairs) - riseOf(v.stairs);
    };
    if (a.top_observed && maxZ(b.stairs) > maxZ(a.stairs) + slack) return false;
    if (b.top_observed && maxZ(a.stairs) > maxZ(b.stairs) + slack) return false;
    if (a.bottom_observed && minZ(b.stairs) < bottomFloor(a) + slack) return false;
    if (b.bottom_observed && minZ(a.stairs) < bottomFloor(b) + slack) return false;
    return true;
}

}  // namespace stairmap::fleet
