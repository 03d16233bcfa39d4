#include "core/StartSurface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace stairmap {
namespace {

/// [-] lateral bins across the flight for a band's spread (min_spread_fraction of them)
constexpr int kSpreadBins = 20;
/// [m] height resolution of the band search (band_m is a whole number of these)
constexpr double kHeightBin = 0.005;

struct HeightBin {
    int points = 0;
    double z_sum = 0.0;        ///< [m] summed heights of the points
    std::uint32_t across = 0;  ///< bit k: a point in lateral bin k
};

/// The window in front of the first edge: a frame at its centre (u along it, up towards the
/// flight) and the ranges across (t), along (s, negative in front) and in height.
struct FrontWindow {
    Eigen::Vector2d c = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::Zero(),
                    up = Eigen::Vector2d::Zero();
    double t_lo = 0, t_hi = 0, s_lo = 0, s_hi = 0, z_lo = 0, z_hi = 0;
    bool valid = false;
};

FrontWindow frontWindow(const std::vector<LineSegment>& edges, double rise, double run,
                        const StartSurfaceParams& p) {
    FrontWindow w;
    if (edges.size() < 2 || !(run > 0) || !(rise > p.min_deficit_m + p.min_below_edge_m)) return w;
    const LineSegment& first = edges.front();
    w.c = first.centre();
    w.u = first.direction();
    const Eigen::Vector2d in_front = 2.0 * w.c - edges.back().centre();  // one flight's length
    w.up = first.normalAwayFrom(in_front);
    // Across the flight: where most edges reach (the median of their ends along the first edge;
    // a far flight's first edge, a riser hit, is often a short piece), less the ends.
    std::vector<double> lo, hi;
    for (const LineSegment& e : edges) {
        const double a = w.u.dot(e.start - w.c), b = w.u.dot(e.end - w.c);
        lo.push_back(std::min(a, b));
        hi.push_back(std::max(a, b));
    }
    std::nth_element(lo.begin(), lo.begin() + lo.size() / 2, lo.end());
    std::nth_element(hi.begin(), hi.begin() + hi.size() / 2, hi.end());
    const double t_lo0 = lo[lo.size() / 2], t_hi0 = hi[hi.size() / 2];
    const double trim = p.end_fraction * (t_hi0 - t_lo0);
    w.t_lo = t_lo0 + trim;
    w.t_hi = t_hi0 - trim;
    w.s_lo = -std::max(p.to_runs * run, p.min_reach_m);
    w.s_hi = -p.from_runs * run;
    w.z_lo = first.z - rise - p.below_rise_margin_m;
    w.z_hi = first.z - p.min_below_edge_m;
    w.valid = w.t_hi > w.t_lo;
    return w;
}

}  // namespace

FlightBox startWindowBox(const std::vector<LineSegment>& edges, double rise, double run,
                         const StartSurfaceParams& p) {
    const FrontWindow w = frontWindow(edges, rise, run, p);
    FlightBox box;
    box.lo = box.hi = w.c;
    box.z_lo = w.z_lo;
    box.z_hi = w.z_hi;
    if (!w.valid) {  // an empty box, whatever is added to its bounds
        box.z_lo = std::numeric_limits<double>::infinity();
        box.z_hi = -std::numeric_limits<double>::infinity();
        return box;
    }
    for (const double t : {w.t_lo, w.t_hi})
        for (const double s : {w.s_lo, w.s_hi}) {
            const Eigen::Vector2d corner = w.c + t * w.u + s * w.up;
            box.lo = box.lo.cwiseMin(corner);
            box.hi = box.hi.cwiseMax(corner);
        }
    return box;
}

std::optional<double> startSurfaceHeight(const PointCloud& cloud,
                                         const std::vector<LineSegment>& edges, double rise,
                                         double run, const StartSurfaceParams& p) {
    const FrontWindow w = frontWindow(edges, rise, run, p);
    if (!w.valid) return std::nullopt;
    const double width = w.t_hi - w.t_lo;
    // Heights in bins of kHeightBin: per bin the points, their summed height and the lateral
    // bins they fall in (one bit each), so the band slides over bins, not sorted points.
    const int z_bins = static_cast<int>((w.z_hi - w.z_lo) / kHeightBin) + 1;
    std::vector<HeightBin> bins(static_cast<std::size_t>(std::max(z_bins, 1)));
    for (const Eigen::Vector3f& q : cloud) {
        if (!(q.z() >= w.z_lo && q.z() <= w.z_hi)) continue;  // NaN too
        const Eigen::Vector2d d(q.x() - w.c.x(), q.y() - w.c.y());
        const double s = w.up.dot(d), t = w.u.dot(d);
        if (!(s >= w.s_lo && s <= w.s_hi && t >= w.t_lo && t <= w.t_hi)) continue;  // NaN too
        const int across =
            std::min(kSpreadBins - 1, static_cast<int>((t - w.t_lo) / width * kSpreadBins));
        HeightBin& h = bins[std::min(z_bins - 1, static_cast<int>((q.z() - w.z_lo) / kHeightBin))];
        ++h.points;
        h.z_sum += q.z();
        h.across |= 1u << across;
    }
    // The band of band_m holding the most points (the lowest of equals), spread across the flight.
    const int band = std::max(1, static_cast<int>(std::lround(p.band_m / kHeightBin)));
    const int min_span = static_cast<int>(std::ceil(p.min_spread_fraction * kSpreadBins));
    std::optional<double> best;
    int best_points = p.min_points - 1;
    for (int i = 0; i + band <= z_bins || (i == 0 && z_bins < band); ++i) {
        int points = 0;
        double z_sum = 0.0;
        std::uint32_t across = 0;
        for (int k = i; k < std::min(i + band, z_bins); ++k) {
            points += bins[k].points;
            z_sum += bins[k].z_sum;
            across |= bins[k].across;
        }
        if (points <= best_points || across == 0) continue;
        const int span = 32 - __builtin_clz(across) - __builtin_ctz(across);
        if (span < min_span) continue;
        best_points = points;
        best = z_sum / points;  // the band's mean height
    }
    return best;
}

std::optional<double> lowEdgesStart(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                                    double rise, double run, double floor_z,
                                    const StartSurfaceParams& p) {
    if (const auto seen = startSurfaceHeight(cloud, edges, rise, run, p)) return seen;
    if (edges.empty()) return std::nullopt;
    const double above_floor = edges.front().z - floor_z;
    if (above_floor >= p.min_below_edge_m && above_floor <= rise - p.min_deficit_m) return floor_z;
    return std::nullopt;
}

bool fitEdgesOnStartSurface(double start_z, const std::vector<double>& upper, double rise,
                            std::vector<LineSegment>& edges, const StartSurfaceParams& p) {
    if (edges.empty() || upper.size() != edges.size()) return false;
    if (edges.front().z >= start_z + rise - p.min_deficit_m) return false;  // not low
    // Z_k = start_z + (k + 1) b within [z_k - tol, upper_k + tol] bounds b from both sides.
    double b_lo = p.min_rise_m, b_hi = p.max_rise_m;
    bool bounded_above = false;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const double steps = static_cast<double>(k + 1);
        if (edges[k].num_points > 0)
            b_lo = std::max(b_lo, (edges[k].z - p.tolerance_m - start_z) / steps);
        if (std::isfinite(upper[k])) {
            b_hi = std::min(b_hi, (upper[k] + p.tolerance_m - start_z) / steps);
            bounded_above = true;
        }
    }
    if (!bounded_above || b_hi < b_lo || b_hi - b_lo > p.max_rise_span_m) return false;
    const double b = 0.5 * (b_lo + b_hi);
    for (std::size_t k = 0; k < edges.size(); ++k)
        edges[k].z = start_z + static_cast<double>(k + 1) * b;
    return true;
}

}  // namespace stairmap
