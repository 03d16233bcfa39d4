#include "core/RayClearance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/FlightPoints.h"

namespace stairmap {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Unit normal of `edge` pointing up the flight (towards the next edge, or away from the previous
/// one for the last edge).
Eigen::Vector2d upFlightNormal(const std::vector<LineSegment>& edges, std::size_t k) {
    const LineSegment& e = edges[k];
    const Eigen::Vector2d up = edges.back().centre() - edges.front().centre();
    const Eigen::Vector2d along = (e.end - e.start).normalized();
    Eigen::Vector2d n(-along.y(), along.x());
    if (n.dot(up) < 0) n = -n;
    return n;
}

/// Offsets [a_lo, a_hi] of the lines z = a + b k with rise `b` inside every edge's bounds
/// [edge z, upper] widened by `tolerance` (empty when a_hi < a_lo).
std::pair<double, double> feasibleOffsets(const std::vector<LineSegment>& edges,
                                          const std::vector<double>& upper, double b,
                                          double tolerance) {
    double a_lo = -kInfinity, a_hi = kInfinity;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        a_lo = std::max(a_lo, edges[k].z - tolerance - b * k);
        if (std::isfinite(upper[k])) a_hi = std::min(a_hi, upper[k] + tolerance - b * k);
    }
    return {a_lo, a_hi};
}

/// The rays that cleared edge k: the heights where the rays to the points behind it (min_behind_m
/// to max_behind_runs runs, through the middle of the edge, not under it) cross its line. Only
/// the `rank` lowest are kept: the bound is the rank-th lowest, which no higher one changes (a
/// dense cloud has tens of thousands of rays behind an edge).
struct ClearanceProbe {
    Eigen::Vector2d n, u, c;
    double edge_range = 0, z = 0, beside_lo = 0, beside_hi = 0, min_behind = 0, max_behind = 0;
    double under_slack = 0;
    std::size_t step = 0;         ///< k
    std::size_t rank = 1;         ///< clearance_rank
    bool looks_at_riser = false;  ///< the sensor (origin) looks at the riser's face
    std::vector<double> lowest;   ///< the lowest clearances so far, ascending, at most rank

    void add(const Eigen::Vector3f& q) {
        const Eigen::Vector2d xy(q.x(), q.y());
        const double range = n.dot(xy);
        const double behind = range - edge_range;
        if (!(behind >= min_behind && behind <= max_behind)) return;  // NaN too
        const double t = edge_range / range;  // where the ray from the origin crosses the line
        const double beside = u.dot(t * xy - c);
        if (beside < beside_lo || beside > beside_hi) return;
        const double h = t * q.z();
        // Passed under the tread or beside the flight (or a NaN height: no ray)
        if (!(h >= z - under_slack)) return;
        keep(h);
    }
    void keep(double h) {
        if (lowest.size() == rank && h >= lowest.back()) return;
        lowest.insert(std::upper_bound(lowest.begin(), lowest.end(), h), h);
        if (lowest.size() > rank) lowest.pop_back();
    }
    /// The rank-th lowest clearance, +infinity when fewer rays cleared the edge.
    double upperBound() const {
        return looks_at_riser && lowest.size() == rank ? lowest.back() : kInfinity;
    }
};

ClearanceProbe clearanceProbe(const std::vector<LineSegment>& edges, std::size_t k, double run,
                              const RayClearanceParams& p) {
    const LineSegment& e = edges[k];
    ClearanceProbe r;
    r.step = k;
    r.n = upFlightNormal(edges, k);
    r.u = Eigen::Vector2d(-r.n.y(), r.n.x());
    r.c = e.centre();
    r.edge_range = r.n.dot(r.c);
    r.looks_at_riser = r.edge_range > p.min_behind_m;
    r.z = e.z;
    const double a = r.u.dot(e.start - r.c), b = r.u.dot(e.end - r.c);
    const double trim = p.end_fraction * std::abs(b - a);
    r.beside_lo = std::min(a, b) + trim;
    r.beside_hi = std::max(a, b) - trim;
    r.min_behind = p.min_behind_m;
    r.max_behind = p.max_behind_runs * run;
    r.under_slack = p.under_slack_m;
    r.rank = static_cast<std::size_t>(std::max(1, p.clearance_rank));
    return r;
}

}  // namespace

double nosingClearance(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                       std::size_t k, double run, const RayClearanceParams& p) {
    if (k >= edges.size() || edges.size() < 2 || !(run > 0)) return kInfinity;
    ClearanceProbe r = clearanceProbe(edges, k, run, p);
    if (!r.looks_at_riser) return kInfinity;
    for (const Eigen::Vector3f& q : cloud) r.add(q);
    return r.upperBound();
}

std::vector<double> nosingClearances(const PointCloud& cloud, const FlightBox& box,
                                     const std::vector<LineSegment>& edges, double run,
                                     const RayClearanceParams& p) {
    std::vector<double> upper(edges.size(), kInfinity);
    if (edges.size() < 2 || !(run > 0)) return upper;
    std::vector<ClearanceProbe> probes;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        probes.push_back(clearanceProbe(edges, k, run, p));
        if (!probes.back().looks_at_riser) probes.pop_back();
    }
    for (const Eigen::Vector3f& q : cloud) {
        if (!box.contains(q)) continue;
        for (ClearanceProbe& r : probes) r.add(q);
    }
    for (ClearanceProbe& r : probes) upper[r.step] = r.upperBound();
    return upper;
}

std::vector<double> edgeClearances(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                                   double rise, double run, const RayClearanceParams& p) {
    if (edges.size() < 2 || !(rise > 0) || !(run > 0))
        return std::vector<double>(edges.size(), kInfinity);
    double z_lo = kInfinity;
    for (const LineSegment& e : edges) z_lo = std::min(z_lo, e.z);
    const double reach = p.max_behind_runs * run + p.min_behind_m;
    const double z_hi = edges.back().z + (p.max_behind_runs + 2.0) * rise;
    // Points that can bound the edges: rays to anything higher clear the nosings by far.
    const FlightBox box = flightBox(edges, reach, z_lo - p.under_slack_m, z_hi);
    return nosingClearances(cloud, box, edges, run, p);
}

int fitEdgesToRayClearance(const PointCloud& cloud, double rise, double run,
                           std::vector<LineSegment>& edges, const RayClearanceParams& p) {
    if (edges.size() < 2 || !(rise > 0) || !(run > 0)) return 0;
    return fitEdgesToRayClearance(edgeClearances(cloud, edges, rise, run, p), rise, edges, p);
}

int fitEdgesToRayClearance(const std::vector<double>& upper, double rise,
                           std::vector<LineSegment>& edges, const RayClearanceParams& p) {
    if (edges.size() < 2 || upper.size() != edges.size() || !(rise > 0)) return 0;
    const int bounded = static_cast<int>(
        std::count_if(upper.begin(), upper.end(), [](double u) { return std::isfinite(u); }));
    if (bounded < p.min_bounded_edges) return 0;
    // Lines z = a + b k inside every interval: for each rise b the offsets a form an interval;
    // the centroid of that feasible set (weighted by its width) is the estimate.
    double weight = 0, b_sum = 0, a_sum = 0;
    const int steps = static_cast<int>(std::ceil(p.rise_search_m / p.rise_step_m));
    for (int s = -steps; s <= steps; ++s) {
        const double b = rise + s * p.rise_step_m;
        const auto [a_lo, a_hi] = feasibleOffsets(edges, upper, b, p.tolerance_m);
        if (a_hi < a_lo) continue;
        const double w = a_hi - a_lo + 1e-4;  // a single feasible line still counts
        weight += w;
        b_sum += w * b;
        a_sum += w * 0.5 * (a_lo + a_hi);
    }
    if (weight <= 0) return 0;
    const double a = a_sum / weight, b = b_sum / weight;
    const auto [a_lo, a_hi] = feasibleOffsets(edges, upper, b, p.tolerance_m);
    if (a_hi - a_lo > p.max_feasible_width_m) return 0;  // rings in step with the rise: no fix
    int moved = 0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const double z = a + b * static_cast<double>(k);
        if (std::abs(z - edges[k].z) > 1e-3) ++moved;
        edges[k].z = z;
    }
    return moved;
}

}  // namespace stairmap
