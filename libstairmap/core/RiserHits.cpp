#include "core/RiserHits.h"

#include <algorithm>
#include <cmath>

#include "core/LineFusion.h"

namespace stairmap {
namespace {

/// True when `low` lies under `high`: both of its end points within max_offset of high's line,
/// lower by a riser's height at most, and covered by high along the line.
bool isUnder(const LineSegment& low, const LineSegment& high, const RiserHitParams& p) {
    const double dz = high.z - low.z;
    if (dz < p.min_dz_m || dz > p.max_dz_m) return false;
    if (std::abs(high.distanceTo(low.start)) > p.max_offset_xy_m ||
        std::abs(high.distanceTo(low.end)) > p.max_offset_xy_m)
        return false;
    const Eigen::Vector2d u = high.direction();
    const auto el = extentAlong(low, u), eh = extentAlong(high, u);
    const double cover = std::min(el.second, eh.second) - std::max(el.first, eh.first);
    return cover >= p.min_cover * low.length();
}

/// Least-squares z = a + b * i over the edges with keep[i]; false with fewer than 2.
bool fitHeights(const std::vector<LineSegment>& edges, const std::vector<char>& keep, double& a,
                double& b) {
    double n = 0, si = 0, sz = 0, sii = 0, siz = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (!keep[i]) continue;
        n += 1;
        si += i;
        sz += edges[i].z;
        sii += static_cast<double>(i) * i;
        siz += i * edges[i].z;
    }
    const double den = n * sii - si * si;
    if (n < 2 || std::abs(den) < 1e-12) return false;
    b = (n * siz - si * sz) / den;
    a = (sz - b * si) / n;
    return true;
}

}  // namespace

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
    std::vector<char> drop(lines.size(), 0);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        for (std::size_t j = 0; j < lines.size() && !drop[i]; ++j) {
            if (j != i && isUnder(lines[i], lines[j], params)) drop[i] = 1;
        }
    }
    std::size_t w = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (!drop[i]) lines[w++] = lines[i];
    }
    lines.resize(w);
}

}  // namespace stairmap
