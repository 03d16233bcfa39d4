#include "core/StaircaseGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace stairmap {
namespace {

/// [-] fewest pairs of seen edges for the median run (three seen edges); fewer: least squares
constexpr std::size_t kMinRunPairs = 3;

/// Distance from an XY point to the infinite XY line through an edge.
double pointToLineXY(const Eigen::Vector2d& p, const StairEdge& e) {
    const Eigen::Vector2d a = e.start.head<2>();
    const Eigen::Vector2d d = (e.end - e.start).head<2>();
    const double len = d.norm();
    if (len < 1e-12) return (p - a).norm();
    return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / len;
}

/// Length-weighted mean orientation of the edges (orientations are axial: average 2*alpha).
double meanOrientation(const std::vector<StairEdge>& steps) {
    double c = 0.0, s = 0.0;
    for (const auto& e : steps) {
        const double a = e.orientationRad();
        const double w = std::max(e.length(), 1e-6);
        c += w * std::cos(2 * a);
        s += w * std::sin(2 * a);
    }
    return 0.5 * std::atan2(s, c);
}

double robustWidth(const std::vector<StairEdge>& steps) {
    std::vector<double> lengths;
    lengths.reserve(steps.size());
    for (const auto& e : steps) lengths.push_back(e.length());
    std::sort(lengths.begin(), lengths.end());
    // Median of the longer half: partially seen (short) edges do not pull the width down.
    const std::size_t first = lengths.size() / 2;
    const std::size_t n = lengths.size() - first;
    const std::size_t mid = first + n / 2;
    return (n % 2 == 1) ? lengths[mid] : 0.5 * (lengths[mid - 1] + lengths[mid]);
}


double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

/// Straight flights only: an edge seen only in part (descending flights at an angle hide the ends
/// of the first nosings) is lengthened, along its own fitted line, to the flight's lateral extent
/// (median ends of the well-observed edges, length >= 80 % of the robust width). Observed extent is
/// never shortened. The location (centre of steps[0]) then no longer shifts sideways.
void completePartialEdges(std::vector<StairEdge>& steps, double alpha, double width) {
    constexpr double kMaxTurnRad = 10.0 * M_PI / 180.0;  // beyond this the flight turns (spiral)
    const Eigen::Vector2d lateral(std::cos(alpha), std::sin(alpha));
    std::vector<double> los, his;
    for (const auto& e : steps) {
        if (std::abs(std::remainder(e.orientationRad() - alpha, M_PI)) > kMaxTurnRad) return;
        if (e.length() < 0.8 * width) continue;
        const auto [lo, hi] = lateralExtent(e, lateral);
        los.push_back(lo);
        his.push_back(hi);
    }
    if (los.size() < 2) return;
    const double flight_lo = median(los), flight_hi = median(his);
    for (auto& e : steps) {
        if (e.length() >= 0.8 * width) continue;
        Eigen::Vector3d u = e.end - e.start;
        u.z() = 0.0;
        const double denom = lateral.dot(u.head<2>().normalized());
        if (u.norm() < 1e-9 || std::abs(denom) < 0.9) continue;
        u /= u.norm() * denom;  // moves one unit along `lateral` per unit of parameter
        const Eigen::Vector3d c = e.centre();
        const double t_c = lateral.dot(c.head<2>());
        const auto [lo, hi] = lateralExtent(e, lateral);
        const Eigen::Vector3d p_lo = c + (std::min(lo, flight_lo) - t_c) * u;
        const Eigen::Vector3d p_hi = c + (std::max(hi, flight_hi) - t_c) * u;
        const bool start_is_lo = lateral.dot(e.start.head<2>()) <= lateral.dot(e.end.head<2>());
        e.start = start_is_lo ? p_lo : p_hi;
        e.end = start_is_lo ? p_hi : p_lo;
    }
}

}  // namespace

double slopeAgainstIndex(const std::vector<double>& values) {
    const int k = static_cast<int>(values.size());
    if (k < 2) return 0.0;
    const double i_mean = 0.5 * (k - 1);
    double v_mean = 0.0;
    for (double v : values) v_mean += v;
    v_mean /= k;
    double num = 0.0, den = 0.0;
    for (int i = 0; i < k; ++i) {
        num += (i - i_mean) * (values[i] - v_mean);
        den += (i - i_mean) * (i - i_mean);
    }
    return num / den;
}

double lineFitError(const std::vector<double>& x, const std::vector<double>& v, double* slope) {
    const double n = static_cast<double>(x.size());
    double sx = 0, sv = 0, sxx = 0, sxv = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += x[i];
        sv += v[i];
        sxx += x[i] * x[i];
        sxv += x[i] * v[i];
    }
    const double det = n * sxx - sx * sx;
    if (!(det > 0)) return std::numeric_limits<double>::infinity();
    const double b = (n * sxv - sx * sv) / det, a = (sv - b * sx) / n;
    if (slope) *slope = b;
    double worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
        worst = std::max(worst, std::abs(v[i] - a - b * x[i]));
    return worst;
}

double medianPairwiseSlope(const std::vector<double>& values, const std::vector<char>& seen,
                           std::size_t min_pairs) {
    std::vector<double> slopes;
    for (std::size_t i = 0; i < values.size(); ++i)
        for (std::size_t j = i + 1; j < values.size(); ++j)
            if (seen[i] && seen[j])
                slopes.push_back((values[j] - values[i]) / static_cast<double>(j - i));
    if (slopes.empty() || slopes.size() < min_pairs) return slopeAgainstIndex(values);
    const auto mid = slopes.begin() + static_cast<std::ptrdiff_t>(slopes.size() / 2);
    std::nth_element(slopes.begin(), mid, slopes.end());
    return *mid;
}

std::vector<char> seenEdges(const std::vector<StairEdge>& steps) {
    std::vector<char> seen;
    seen.reserve(steps.size());
    for (const StairEdge& e : steps) seen.push_back(e.num_points > 0);
    return seen;
}

std::pair<double, double> lateralExtent(const Staircase& s, const Eigen::Vector2d& lateral) {
    std::pair<double, double> ext{std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity()};
    for (const StairEdge& e : s.steps) {
        const auto x = lateralExtent(e, lateral);
        ext = {std::min(ext.first, x.first), std::max(ext.second, x.second)};
    }
    return ext;
}

std::pair<double, double> lateralExtent(const StairEdge& e, const Eigen::Vector2d& lateral) {
    const double a = lateral.dot(e.start.head<2>()), b = lateral.dot(e.end.head<2>());
    return {std::min(a, b), std::max(a, b)};
}

double edgeSpacingXY(const StairEdge& a, const StairEdge& b) {
    return 0.5 * (pointToLineXY(a.centre().head<2>(), b) + pointToLineXY(b.centre().head<2>(), a));
}

void estimateGeometry(Staircase& stairs) {
    const auto& steps = stairs.steps;
    if (steps.empty()) {
        stairs.step_height = stairs.step_depth = stairs.step_width = stairs.slope_rad = 0.0;
        stairs.location.setZero();
        return;
    }
    const double alpha = meanOrientation(steps);
    Eigen::Vector2d normal(-std::sin(alpha), std::cos(alpha));
    const Eigen::Vector2d outward =
        steps.size() > 1 ? Eigen::Vector2d((steps.back().centre() - steps.front().centre()).head<2>())
                         : Eigen::Vector2d(std::cos(stairs.heading_rad), std::sin(stairs.heading_rad));
    if (normal.dot(outward) < 0) normal = -normal;
    stairs.heading_rad = std::atan2(normal.y(), normal.x());

    std::vector<double> heights, cumulative;
    double run_sum = 0.0;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        heights.push_back(steps[i].centre().z());
        if (i > 0) run_sum += edgeSpacingXY(steps[i - 1], steps[i]);
        cumulative.push_back(run_sum);
    }
    stairs.step_height = std::abs(slopeAgainstIndex(heights));
    // The run over the seen edges' pairs (put-back edges are interpolated): one edge misplaced (a
    // view's last, short edge at a crop, 43 deg off the others: dev3 r0076, 4.2 cm short; a depth
    // camera's noisy one) tilts the least-squares slope of the cumulative spacing. Run MAE dev /
    // dev2 / dev3 0.395 / 0.543 / 0.506 -> 0.351 / 0.506 / 0.436 cm; all edges' pairs 0.350 /
    // 0.505 / 0.456.
    stairs.step_depth = medianPairwiseSlope(cumulative, seenEdges(steps), kMinRunPairs);
    stairs.step_width = robustWidth(steps);
    stairs.slope_rad = std::atan2(stairs.step_height, stairs.step_depth);
    // Only descending flights: there the floor's edge hides the ends of the first lower nosings when
    // seen at an angle. (On the two-floor run, completing ascending edges moved stair_a's location
    // 20 cm further from the truth: its well-observed edges were themselves cut by the near wall.)
    if (stairs.direction == StairDirection::Descending)
        completePartialEdges(stairs.steps, alpha, stairs.step_width);
    stairs.location = steps.front().centre();
}

Eigen::Vector2d outwardNormal(const Staircase& s, std::size_t k) {
    const Eigen::Vector2d d = (s.steps[k].end - s.steps[k].start).head<2>();
    Eigen::Vector2d n(-d.y(), d.x());
    if (n.norm() < 1e-9) n = Eigen::Vector2d(std::cos(s.heading_rad), std::sin(s.heading_rad));
    n.normalize();
    const std::size_t lo = k > 0 ? k - 1 : k, hi = k + 1 < s.steps.size() ? k + 1 : k;
    const Eigen::Vector2d flow = (s.steps[hi].centre() - s.steps[lo].centre()).head<2>();
    const Eigen::Vector2d heading(std::cos(s.heading_rad), std::sin(s.heading_rad));
    return n.dot(lo == hi ? heading : flow) >= 0 ? n : Eigen::Vector2d(-n);
}

double flightStartZ(const Staircase& s) {
    const double first = s.steps.front().centre().z();
    return s.direction == StairDirection::Ascending ? first - s.step_height : first;
}

}  // namespace stairmap
