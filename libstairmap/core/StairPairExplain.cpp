#include "core/StairPairExplain.h"

#include <algorithm>
#include <cmath>

#include "core/LineFusion.h"
#include "core/StairSearch.h"

namespace stairmap {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

/// v with `decimals` digits after the point (the core has no printf).
std::string fixed(double v, int decimals) {
    const long long scale = decimals == 0 ? 1 : decimals == 1 ? 10 : 100;
    const long long r = std::llround(std::abs(v) * static_cast<double>(scale));
    std::string s = std::to_string(r / scale);
    if (decimals > 0) {
        const std::string f = std::to_string(r % scale);
        s += "." + std::string(static_cast<std::size_t>(decimals) - f.size(), '0') + f;
    }
    return (v < 0 && r != 0 ? "-" : "") + s;
}

/// "<what> <value> <op> <limit><unit>", metres with 2 decimals, degrees with none.
std::string rule(const char* what, double value, const char* op, double limit, bool degrees) {
    const int d = degrees ? 0 : 2;
    const char* unit = degrees ? "°" : " m";
    return std::string(what) + " " + fixed(value, d) + (degrees ? "°" : "") + " " + op + " " +
           fixed(limit, d) + unit;
}

/// The first failed threshold among rise, parallelism, run and slope ("" if all hold).
std::string explainMeasures(const LineSegment& lower, const LineSegment& upper,
                            const DetectorParams& p) {
    const double tol = p.edge_height_tolerance_m;
    const double rise = upper.z - lower.z;
    if (rise < p.min_step_height_m - tol)
        return rule("rise", rise, "<", p.min_step_height_m - tol, false);
    if (rise > p.max_step_height_m + tol)
        return rule("rise", rise, ">", p.max_step_height_m + tol, false);
    const double angle = lineAngle(lower, upper) / kDegToRad;
    if (angle > p.max_parallel_deg)
        return "not parallel: " + fixed(angle, 0) + "° > " + fixed(p.max_parallel_deg, 0) + "°";
    const Eigen::Vector2d n_low(std::cos(lower.theta), std::sin(lower.theta));
    const Eigen::Vector2d n_up(std::cos(upper.theta), std::sin(upper.theta));
    const double run = 0.5 * (std::abs(n_up.dot(lower.centre()) - upper.rho) +
                              std::abs(n_low.dot(upper.centre()) - lower.rho));
    if (run < p.min_step_depth_m) return rule("run", run, "<", p.min_step_depth_m, false);
    if (run > p.max_step_depth_m) return rule("run", run, ">", p.max_step_depth_m, false);
    const double steepest = std::atan2(rise + tol, run) / kDegToRad;
    if (steepest < p.min_slope_deg) return rule("slope", steepest, "<", p.min_slope_deg, true);
    const double flattest = std::atan2(std::max(0.0, rise - tol), run) / kDegToRad;
    if (flattest > p.max_slope_deg) return rule("slope", flattest, ">", p.max_slope_deg, true);
    return "";
}

}  // namespace

std::string explainStairPair(const LineSegment& lower, const LineSegment& upper,
                             const DetectorParams& p) {
    std::string why = explainMeasures(lower, upper, p);
    if (!why.empty()) return why;
    if (!checkStairPair(lower, upper, p)) {
        // Every other threshold held: only the lateral overlap is left.
        return "overlap < " + fixed(100.0 * p.min_overlap_ratio, 0) + "% of " +
               fixed(std::min(lower.length(), upper.length()), 2) + " m";
    }
    return "";
}

std::string tooFewSteps(std::size_t steps, int min_steps) {
    return std::to_string(steps) + " steps < " + std::to_string(min_steps);
}

void explainRefusedPairs(const std::vector<LineSegment>& lines, const std::vector<char>& used,
                         StairDirection direction, double floor_z, const DetectorParams& p,
                         std::vector<RejectedChain>& out) {
    const double reach_xy = 2.0 * p.max_step_depth_m;
    const double reach_z = 2.0 * p.max_step_height_m;
    for (std::size_t i = 0; i < lines.size() && out.size() < DetectorDebug::kMaxRejected; ++i) {
        if (used[i]) continue;
        // The nearest line above (3D centre distance) that could be the next step.
        int best = -1;
        double best_d2 = reach_xy * reach_xy + reach_z * reach_z;
        for (std::size_t j = i + 1; j < lines.size() && lines[j].z - lines[i].z <= reach_z; ++j) {
            if (used[j] || lines[j].z - lines[i].z < 0.5 * p.min_step_height_m) continue;
            const Eigen::Vector2d d = lines[j].centre() - lines[i].centre();
            if (d.norm() > reach_xy) continue;
            const double dz = lines[j].z - lines[i].z;
            const double d2 = d.squaredNorm() + dz * dz;
            if (d2 < best_d2) best = static_cast<int>(j), best_d2 = d2;
        }
        if (best < 0) continue;
        std::string why = explainStairPair(lines[i], lines[best], p);
        if (why.empty()) {
            const auto pair = checkStairPair(lines[i], lines[best], p);
            if (!hasLineBetween(lines, static_cast<int>(i), best, *pair, p)) continue;
            why = "a line in between";
        }
        RejectedChain chain{direction, {lines[i], lines[best]}, why};
        if (direction == StairDirection::Descending)
            for (auto& e : chain.edges) e.z = 2 * floor_z - e.z;
        out.push_back(std::move(chain));
    }
}

}  // namespace stairmap
