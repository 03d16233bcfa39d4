#include "core/StaircaseCanonical.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace stairmap {
namespace {

bool isFinite(const Staircase& s) {
    for (const StairEdge& e : s.steps) {
        if (!e.start.allFinite() || !e.end.allFinite() || !e.cov_rho_theta.allFinite()) return false;
    }
    return std::isfinite(s.heading_rad) && std::isfinite(s.step_height) &&
           std::isfinite(s.step_depth);
}

/// Length-weighted mean edge direction (edges have no sign: fold onto the first edge's).
Eigen::Vector2d meanEdgeDirection(const Staircase& s) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Vector2d ref = Eigen::Vector2d::Zero();
    for (const StairEdge& e : s.steps) {
        Eigen::Vector2d d = (e.end - e.start).head<2>();
        if (ref.squaredNorm() == 0.0) ref = d;
        sum += (d.dot(ref) < 0.0) ? Eigen::Vector2d(-d) : d;
    }
    return sum;
}

void orientEdges(Staircase& s) {
    const Eigen::Vector2d u = headingVector(s);
    const Eigen::Vector2d left(-u.y(), u.x());
    for (StairEdge& e : s.steps) {
        if ((e.end - e.start).head<2>().dot(left) > 0.0) std::swap(e.start, e.end);
    }
}

void updateHeading(Staircase& s) {
    if (s.steps.size() < 2) return;  // a single edge cannot tell uphill from downhill
    const Eigen::Vector2d d = meanEdgeDirection(s);
    if (d.squaredNorm() < 1e-12) return;
    Eigen::Vector2d normal(-d.y(), d.x());
    const Eigen::Vector2d rise = (s.steps.back().centre() - s.steps.front().centre()).head<2>();
    if (normal.dot(rise) < 0.0) normal = -normal;
    s.heading_rad = std::atan2(normal.y(), normal.x());
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t k = v.size();
    return (k % 2) ? v[k / 2] : 0.5 * (v[k / 2 - 1] + v[k / 2]);
}

/// Rise and run as least-squares slopes of edge height and of position along the heading
/// against the step level. Levels come from the heights, so steps never seen (a gap between
/// two partial views of one flight) do not bias the estimate.
void fitRiseAndRun(Staircase& s) {
    const std::size_t k = s.steps.size();
    std::vector<double> dz;
    for (std::size_t i = 0; i + 1 < k; ++i) {
        dz.push_back(s.steps[i + 1].centre().z() - s.steps[i].centre().z());
    }
    const double rise0 = median(dz);
    if (!(rise0 > 0.02)) return;  // not a staircase-like sequence: keep the previous values
    const Eigen::Vector2d u = headingVector(s);
    const double z0 = s.steps.front().centre().z();
    double sl = 0, sz = 0, sp = 0, sll = 0, slz = 0, slp = 0;
    for (const StairEdge& e : s.steps) {
        const double level = std::round((e.centre().z() - z0) / rise0);
        const double z = e.centre().z(), p = e.centre().head<2>().dot(u);
        sl += level, sz += z, sp += p, sll += level * level, slz += level * z, slp += level * p;
    }
    const double n = static_cast<double>(k);
    const double var = sll - sl * sl / n;
    if (var <= 0.0) return;
    s.step_height = (slz - sl * sz / n) / var;
    s.step_depth = (slp - sl * sp / n) / var;
}

}  // namespace

Eigen::Vector2d headingVector(const Staircase& staircase) {
    return {std::cos(staircase.heading_rad), std::sin(staircase.heading_rad)};
}

void updateCanonicalGeometry(Staircase& s) {
    s.direction = StairDirection::Ascending;
    if (s.steps.empty()) return;
    updateHeading(s);
    orientEdges(s);
    const std::size_t k = s.steps.size();
    // Median edge length: robust to a partially seen or spuriously extended edge.
    std::vector<double> lengths;
    for (const StairEdge& e : s.steps) lengths.push_back(e.length());
    s.step_width = median(lengths);
    s.location = s.steps.front().centre();
    if (k >= 2) fitRiseAndRun(s);
    s.slope_rad = s.step_depth > 0.0 ? std::atan2(s.step_height, s.step_depth) : 0.0;
}

std::optional<Staircase> canonicalStaircase(const Staircase& staircase) {
    if (staircase.steps.empty() || !isFinite(staircase)) return std::nullopt;
    Staircase s = staircase;
    // A descending staircase is seen from the top: its heading points downhill.
    if (s.direction == StairDirection::Descending) {
        s.heading_rad += M_PI;
        std::swap(s.left_side, s.right_side);  // left/right are taken looking along the heading
    }
    s.heading_rad = std::atan2(std::sin(s.heading_rad), std::cos(s.heading_rad));
    std::stable_sort(s.steps.begin(), s.steps.end(), [](const StairEdge& a, const StairEdge& b) {
        return a.centre().z() < b.centre().z();
    });
    updateCanonicalGeometry(s);
    return s;
}

}  // namespace stairmap
