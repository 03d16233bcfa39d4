#include "core/RiserHits.h"

#include <algorithm>
#include <cmath>

#include "core/LineFusion.h"

namespace stairmap {
namespace {

/// A line's unit normal and direction, computed once (LineSegment derives them from theta on
/// every call, and this test runs for every pair of lines within a rise of each other).
struct Frame {
    Eigen::Vector2d normal, direction;
};

/// True when `low` lies under `high`: both of its end points within max_offset of high's line,
/// lower by a riser's height at most, and covered by high along the line.
bool isUnder(const LineSegment& low, const LineSegment& high, const Frame& h,
             const RiserHitParams& p) {
    const double dz = high.z - low.z;
    if (dz < p.min_dz_m || dz > p.max_dz_m) return false;
    if (std::abs(h.normal.dot(low.start) - high.rho) > p.max_offset_xy_m ||
        std::abs(h.normal.dot(low.end) - high.rho) > p.max_offset_xy_m)
        return false;
    const auto el = extentAlong(low, h.direction), eh = extentAlong(high, h.direction);
    const double cover = std::min(el.second, eh.second) - std::max(el.first, eh.first);
    return cover >= p.min_cover * low.length();
}

/// fitHeightLine over the edges with keep[i].
bool fitHeights(const std::vector<LineSegment>& edges, const std::vector<char>& keep, double& a,
                double& b) {
    std::vector<std::pair<double, double>> samples;
    for (std::size_t i = 0; i < edges.size(); ++i)
        if (keep[i]) samples.emplace_back(static_cast<double>(i), edges[i].z);
    return fitHeightLine(samples, a, b);
}

}  // namespace

bool fitHeightLine(const std::vector<std::pair<double, double>>& samples, double& a, double& b) {
    double n = 0, si = 0, sz = 0, sii = 0, siz = 0;
    for (const auto& [i, z] : samples) {
        n += 1;
        si += i;
        sz += z;
        sii += i * i;
        siz += i * z;
    }
    const double den = n * sii - si * si;
    if (n < 2 || std::abs(den) < 1e-12) return false;
    b = (n * siz - si * sz) / den;
    a = (sz - b * si) / n;
    return true;
}

int raiseLowEdges(std::vector<LineSegment>& edges, double min_drop_m) {
    const std::size_t n = edges.size();
    std::vector<char> keep(n, 1);
    double a = 0, b = 0;
    for (bool changed = true; changed;) {
        if (!fitHeights(edges, keep, a, b)) return 0;
        changed = false;
        for (std::size_t i = 0; i < n; ++i) {
            if (keep[i] && edges[i].z < a + b * i - min_drop_m) {
                keep[i] = 0;
                changed = true;
            }
        }
    }
    const auto kept = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1));
    if (kept < 3 || 2 * kept < n) return 0;
    int raised = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (keep[i]) continue;
        edges[i].z = a + b * i;
        ++raised;
    }
    return raised;
}

void dropRiserHits(std::vector<LineSegment>& lines, const RiserHitParams& params) {
    const std::size_t n = lines.size();
    std::vector<Frame> frames(n);
    std::vector<std::size_t> by_z(n);
    for (std::size_t i = 0; i < n; ++i) {
        frames[i] = {{std::cos(lines[i].theta), std::sin(lines[i].theta)}, lines[i].direction()};
        by_z[i] = i;
    }
    std::sort(by_z.begin(), by_z.end(),
              [&](std::size_t a, std::size_t b) { return lines[a].z < lines[b].z; });
    std::vector<char> drop(n, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = by_z[k];
        // Only the lines up to one rise higher can cover it.
        for (std::size_t m = k + 1; m < n && lines[by_z[m]].z - lines[i].z <= params.max_dz_m;
             ++m) {
            const std::size_t j = by_z[m];
            if (isUnder(lines[i], lines[j], frames[j], params)) {
                drop[i] = 1;
                break;
            }
        }
    }
    std::size_t w = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!drop[i]) lines[w++] = lines[i];
    }
    lines.resize(w);
}

}  // namespace stairmap
