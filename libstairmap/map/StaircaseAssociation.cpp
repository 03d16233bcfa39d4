#include "map/StaircaseAssociation.h"

#include <algorithm>
#include <cmath>

#include "core/StairEdgeFusion.h"
#include "core/StaircaseCanonical.h"
#include "core/StaircaseMerge.h"

namespace stairmap {
namespace {

constexpr double kDegToRad = M_PI / 180.0;
constexpr double kDefaultRise = 0.15;  // [m] used only when a flight has a single step
constexpr double kDefaultRun = 0.25;   // [m]

double angleDiff(double a, double b) {
    return std::abs(std::atan2(std::sin(a - b), std::cos(a - b)));
}

double rise(const Staircase& s) { return s.step_height > 0.0 ? s.step_height : kDefaultRise; }
double run(const Staircase& s) { return s.step_depth > 0.0 ? s.step_depth : kDefaultRun; }

using Polygon = std::vector<Eigen::Vector2d>;

Polygon footprint(const Staircase& s) {
    const Eigen::Vector2d half = 0.5 * run(s) * headingVector(s);
    const StairEdge& lo = s.steps.front();
    const StairEdge& hi = s.steps.back();
    // Corners in order around the quad (made counter-clockwise by the caller).
    return {lo.start.head<2>() - half, hi.start.head<2>() + half, hi.end.head<2>() + half,
            lo.end.head<2>() - half};
}

double signedArea(const Polygon& p) {
    double a = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Eigen::Vector2d& u = p[i];
        const Eigen::Vector2d& v = p[(i + 1) % p.size()];
        a += u.x() * v.y() - v.x() * u.y();
    }
    return 0.5 * a;
}

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

/// Sutherland-Hodgman clipping of `subject` by the convex counter-clockwise `clip`.
Polygon clipConvex(Polygon subject, const Polygon& clip) {
    for (std::size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
        const Eigen::Vector2d& a = clip[i];
        const Eigen::Vector2d& b = clip[(i + 1) % clip.size()];
        Polygon out;
        for (std::size_t j = 0; j < subject.size(); ++j) {
            const Eigen::Vector2d& p = subject[j];
            const Eigen::Vector2d& q = subject[(j + 1) % subject.size()];
            const double cp = cross(a, b, p), cq = cross(a, b, q);
            if (cp >= 0) out.push_back(p);
            if ((cp >= 0) != (cq >= 0)) out.push_back(p + (q - p) * (cp / (cp - cq)));
        }
        subject = std::move(out);
    }
    return subject;
}

Polygon counterClockwise(Polygon p) {
    if (signedArea(p) < 0) std::reverse(p.begin(), p.end());
    return p;
}

/// `upper` continues `lower` (see LandmarkParams::max_extrapolated_steps).
bool continuesFlight(const Staircase& lower, const Staircase& upper, const LandmarkParams& params) {
    if (lower.steps.size() < 2 || upper.steps.size() < 2) return false;
    const double rise_l = rise(lower), run_l = run(lower);
    if (std::abs(rise(upper) - rise_l) > 0.15 * rise_l || std::abs(run(upper) - run_l) > 0.15 * run_l)
        return false;
    const StairEdge& top = lower.steps.back();
    const StairEdge& next = upper.steps.front();
    const long k = std::lround((next.centre().z() - top.centre().z()) / rise_l);
    if (k < 1 || k > params.max_extrapolated_steps + 1) return false;
    StairEdge predicted = top;
    const Eigen::Vector2d shift = static_cast<double>(k) * run_l * headingVector(lower);
    const Eigen::Vector3d offset(shift.x(), shift.y(), static_cast<double>(k) * rise_l);
    predicted.start += offset;
    predicted.end += offset;
    MergeParams widened = toMergeParams(params);
    widened.max_height_diff_m += 0.005 * static_cast<double>(k);
    widened.max_distance_m += 0.01 * static_cast<double>(k);
    return isSameStairEdge(predicted, next, widened);
}

}  // namespace

bool headingsAgree(const Staircase& a, const Staircase& b, const LandmarkParams& params) {
    return angleDiff(a.heading_rad, b.heading_rad) <= params.heading_tolerance_deg * kDegToRad;
}

bool footprintsOverlap(const Staircase& a, const Staircase& b, const LandmarkParams& params) {
    const double za0 = a.steps.front().centre().z() - rise(a), za1 = a.steps.back().centre().z();
    const double zb0 = b.steps.front().centre().z() - rise(b), zb1 = b.steps.back().centre().z();
    if (std::min(za1, zb1) - std::max(za0, zb0) < params.footprint_min_z_overlap_m) return false;
    const Polygon pa = counterClockwise(footprint(a));
    const Polygon pb = counterClockwise(footprint(b));
    const double smaller = std::min(std::abs(signedArea(pa)), std::abs(signedArea(pb)));
    if (smaller < 1e-6) return false;
    const Polygon inter = clipConvex(pb, pa);
    if (inter.size() < 3) return false;
    return std::abs(signedArea(inter)) >= params.footprint_min_overlap * smaller;
}

bool sameStaircase(const Staircase& a, const Staircase& b, const LandmarkParams& params) {
    if (a.steps.empty() || b.steps.empty() || !headingsAgree(a, b, params)) return false;
    if (haveCommonStair(a, b, toMergeParams(params))) return true;
    if (params.use_footprint && footprintsOverlap(a, b, params)) return true;
    return params.max_extrapolated_steps > 0 &&
           (continuesFlight(a, b, params) || continuesFlight(b, a, params));
}

}  // namespace stairmap

