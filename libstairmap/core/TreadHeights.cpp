#include "core/TreadHeights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/FlightPoints.h"
#include "core/RiserHits.h"

namespace stairmap {
namespace {

/// Unit normal of `edge` pointing towards `ahead` (the next edge, or up the flight).
Eigen::Vector2d normalTowards(const LineSegment& edge, const Eigen::Vector2d& ahead) {
    const Eigen::Vector2d along = (edge.end - edge.start).normalized();
    Eigen::Vector2d n(-along.y(), along.x());
    if (n.dot(ahead - edge.centre()) < 0) n = -n;
    return n;
}

struct TreadSample {
    float z;       ///< [m] point height
    float beside;  ///< [m] position along the edge
};

/// The lowest band of `samples` (sorted by z) `band` wide holding at least `min_count` of them,
/// spread along the edge over at least `min_spread`: its median height. None when there is none.
std::optional<double> lowestFlatBand(const std::vector<TreadSample>& samples, double band,
                                     int min_count, double min_spread) {
    const std::size_t need = static_cast<std::size_t>(std::max(1, min_count));
    for (std::size_t i = 0, j = 0; i < samples.size(); ++i) {
        j = std::max(j, i);
        while (j < samples.size() && samples[j].z <= samples[i].z + band) ++j;
        if (j - i < need) continue;
        float lo = samples[i].beside, hi = lo;
        for (std::size_t k = i; k < j; ++k) {
            lo = std::min(lo, samples[k].beside);
            hi = std::max(hi, samples[k].beside);
        }
        if (hi - lo >= min_spread) return samples[i + (j - i) / 2].z;
    }
    return std::nullopt;
}

/// Where edge k's tread is looked for: behind the edge by near..far, within its trimmed lateral
/// extent, from below_m under it to max_raise_fraction x rise above it. Collects the points there.
struct TreadWindow {
    Eigen::Vector2d c, n, u;
    double near = 0, far = 0, lo = 0, hi = 0, z_lo = 0, z_hi = 0, min_spread = 0;
    std::vector<TreadSample> samples;

    void add(const Eigen::Vector3f& q) {
        if (q.z() < z_lo || q.z() > z_hi) return;
        const Eigen::Vector2d d(q.x() - c.x(), q.y() - c.y());
        const double behind = n.dot(d), beside = u.dot(d);
        if (behind < near || behind > far || beside < lo || beside > hi) return;
        samples.push_back({q.z(), static_cast<float>(beside)});
    }
};

TreadWindow treadWindow(const std::vector<LineSegment>& edges, std::size_t k, double rise,
                        double run, const TreadHeightParams& p) {
    const LineSegment& e = edges[k];
    const bool last = k + 1 == edges.size();
    const Eigen::Vector2d up_flight = edges.back().centre() - edges.front().centre();
    const Eigen::Vector2d ahead = last ? e.centre() + up_flight : edges[k + 1].centre();
    TreadWindow w;
    w.c = e.centre();
    w.n = normalTowards(e, ahead);
    w.u = Eigen::Vector2d(-w.n.y(), w.n.x());
    const double spacing = last ? run : std::max(0.0, w.n.dot(edges[k + 1].centre() - w.c));
    w.near = p.near_fraction * spacing;
    w.far = p.far_fraction * spacing;
    const double a = w.u.dot(e.start - w.c), b = w.u.dot(e.end - w.c);
    const double trim = p.end_fraction * std::abs(b - a);
    w.lo = std::min(a, b) + trim;
    w.hi = std::max(a, b) - trim;
    w.z_lo = e.z - p.below_m;
    w.z_hi = e.z + p.max_raise_fraction * rise;
    w.min_spread = p.min_spread_fraction * std::abs(b - a);
    return w;
}

bool lowerZ(const TreadSample& x, const TreadSample& y) { return x.z < y.z; }

/// lowestFlatBand of `samples` (in any order) when its band starts at the lowest sample, found
/// without sorting: the band's samples are moved to the front and only their median is put in
/// place. None when the band at the lowest sample does not qualify (a stray point under the
/// tread): the caller then sorts. A dense tread has thousands of samples, nearly all in the band.
std::optional<double> bandAtLowest(std::vector<TreadSample>& samples, double band, int min_count,
                                   double min_spread) {
    const std::size_t need = static_cast<std::size_t>(std::max(1, min_count));
    if (samples.size() < need) return std::nullopt;
    const float lowest = std::min_element(samples.begin(), samples.end(), lowerZ)->z;
    const auto end = std::partition(samples.begin(), samples.end(),
                                    [&](const TreadSample& s) { return s.z <= lowest + band; });
    const std::size_t count = static_cast<std::size_t>(end - samples.begin());
    if (count < need) return std::nullopt;
    const auto [lo, hi] = std::minmax_element(
        samples.begin(), end,
        [](const TreadSample& x, const TreadSample& y) { return x.beside < y.beside; });
    if (hi->beside - lo->beside < min_spread) return std::nullopt;
    const auto median = samples.begin() + count / 2;  // lowestFlatBand's samples[i + (j - i) / 2]
    std::nth_element(samples.begin(), median, end, lowerZ);
    return median->z;
}

/// The tread height of a window filled with its points (see lowestFlatBand), or none.
std::optional<double> treadHeight(TreadWindow& w, const TreadHeightParams& p) {
    if (const auto z = bandAtLowest(w.samples, p.flat_band_m, p.min_points, w.min_spread)) return z;
    std::sort(w.samples.begin(), w.samples.end(), lowerZ);
    return lowestFlatBand(w.samples, p.flat_band_m, p.min_points, w.min_spread);
}

/// The tread heights behind all edges (none where there is no tread), from one pass over the
/// points of `cloud` in `box` (each point is tested against every edge's window).
std::vector<std::optional<double>> treadHeights(const PointCloud& cloud, const FlightBox& box,
                                                const std::vector<LineSegment>& edges,
                                                double rise, double run,
                                                const TreadHeightParams& p) {
    std::vector<TreadWindow> windows;
    for (std::size_t k = 0; k < edges.size(); ++k)
        windows.push_back(treadWindow(edges, k, rise, run, p));
    for (const Eigen::Vector3f& q : cloud) {
        if (!box.contains(q)) continue;
        for (TreadWindow& w : windows) w.add(q);
    }
    std::vector<std::optional<double>> heights;
    for (TreadWindow& w : windows) heights.push_back(treadHeight(w, p));
    return heights;
}

}  // namespace

int raiseEdgesToTreads(const PointCloud& cloud, double rise, double run,
                       std::vector<LineSegment>& edges, const TreadHeightParams& p) {
    if (edges.size() < 2 || !(rise > 0) || !(run > 0)) return 0;
    // Points that can be on a tread: within a run of the edges, from below_m under the lowest edge
    // to the highest raise above the highest.
    double z_lo = std::numeric_limits<double>::infinity(), z_hi = -z_lo;
    for (const LineSegment& e : edges) {
        z_lo = std::min(z_lo, e.z);
        z_hi = std::max(z_hi, e.z);
    }
    const FlightBox box =
        flightBox(edges, run, z_lo - p.below_m, z_hi + p.max_raise_fraction * rise);
    const auto treads = treadHeights(cloud, box, edges, rise, run, p);
    std::vector<std::pair<double, double>> anchors;  // (step index, tread height)
    for (std::size_t k = 0; k < edges.size(); ++k)
        if (treads[k]) anchors.emplace_back(static_cast<double>(k), *treads[k]);
    // Treads are flat and evenly stacked: anchors off the line through the others are something
    // else (a ring on a riser or a post read as a tread) and are dropped, worst first.
    double a = 0, b = 0;
    while (fitHeightLine(anchors, a, b) && static_cast<int>(anchors.size()) >= p.min_anchors) {
        auto worst = anchors.end();
        double worst_residual = p.max_anchor_residual_m;
        for (auto it = anchors.begin(); it != anchors.end(); ++it) {
            const double r = std::abs(it->second - (a + b * it->first));
            if (r > worst_residual) {
                worst_residual = r;
                worst = it;
            }
        }
        if (worst == anchors.end()) break;
        anchors.erase(worst);
    }
    if (static_cast<int>(anchors.size()) < p.min_anchors || !fitHeightLine(anchors, a, b))
        return 0;
    // Riser tops only read low: every edge under the treads' line is raised onto it.
    int raised = 0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const double line_z = a + b * static_cast<double>(k);
        if (line_z > edges[k].z + p.min_raise_m && line_z < edges[k].z + rise) {
            edges[k].z = line_z;
            ++raised;
        }
    }
    return raised;
}

}  // namespace stairmap
