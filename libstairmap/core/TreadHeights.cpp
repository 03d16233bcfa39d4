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

/// The tread height behind edge k (see lowestFlatBand), or none.
std::optional<double> treadHeight(const PointCloud& near_flight,
                                  const std::vector<LineSegment>& edges, std::size_t k,
                                  double rise, double run, const TreadHeightParams& p) {
    const LineSegment& e = edges[k];
    const bool last = k + 1 == edges.size();
    const Eigen::Vector2d up_flight = edges.back().centre() - edges.front().centre();
    const Eigen::Vector2d ahead = last ? e.centre() + up_flight : edges[k + 1].centre();
    const Eigen::Vector2d n = normalTowards(e, ahead);
    const Eigen::Vector2d u(-n.y(), n.x());
    const double spacing = last ? run : std::max(0.0, n.dot(edges[k + 1].centre() - e.centre()));
    const double near = p.near_fraction * spacing, far = p.far_fraction * spacing;
    const double a = u.dot(e.start - e.centre()), b = u.dot(e.end - e.centre());
    const double trim = p.end_fraction * std::abs(b - a);
    const double lo = std::min(a, b) + trim, hi = std::max(a, b) - trim;
    const double z_lo = e.z - p.below_m, z_hi = e.z + p.max_raise_fraction * rise;
    std::vector<TreadSample> samples;
    for (const Eigen::Vector3f& q : near_flight) {
        if (q.z() < z_lo || q.z() > z_hi) continue;
        const Eigen::Vector2d d(q.x() - e.centre().x(), q.y() - e.centre().y());
        const double behind = n.dot(d), beside = u.dot(d);
        if (behind < near || behind > far || beside < lo || beside > hi) continue;
        samples.push_back({q.z(), static_cast<float>(beside)});
    }
    std::sort(samples.begin(), samples.end(),
              [](const TreadSample& x, const TreadSample& y) { return x.z < y.z; });
    return lowestFlatBand(samples, p.flat_band_m, p.min_points,
                          p.min_spread_fraction * std::abs(b - a));
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
    const PointCloud near_flight = pointsNearEdges(cloud, edges, run, z_lo - p.below_m,
                                                   z_hi + p.max_raise_fraction * rise);
    std::vector<std::pair<double, double>> anchors;  // (step index, tread height)
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const auto tread = treadHeight(near_flight, edges, k, rise, run, p);
        if (tread) anchors.emplace_back(static_cast<double>(k), *tread);
    }
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
