#include "core/FlightContinuation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/FlightPoints.h"
#include "core/LineFusion.h"
#include "core/MissingNosings.h"

namespace stairmap {
namespace {

/// The chain's mean rise, mean run and the unit normal of its last edge pointing up the flight.
struct ChainStep {
    double rise = 0.0, run = 0.0;
    Eigen::Vector2d up = Eigen::Vector2d::Zero();
};

ChainStep chainStep(const std::vector<LineSegment>& edges) {
    ChainStep c;
    const LineSegment& first = edges.front();
    const LineSegment& last = edges.back();
    const double n = static_cast<double>(edges.size() - 1);
    c.rise = (last.z - first.z) / n;
    c.up = last.normalAwayFrom(first.centre());
    c.run = c.up.dot(last.centre() - first.centre()) / n;
    return c;
}

/// Every pair's rise and run near the chain's mean, every edge near-parallel to the last.
bool regularStraightChain(const std::vector<LineSegment>& edges, const ChainStep& step,
                          const FlightContinuationParams& p) {
    if (step.rise < p.min_rise_m - p.mean_rise_noise_m) return false;
    const double cos_turn = std::cos(p.max_turn_deg * M_PI / 180.0);
    for (std::size_t i = 1; i < edges.size(); ++i) {
        const double rise = edges[i].z - edges[i - 1].z;
        const double run = step.up.dot(edges[i].centre() - edges[i - 1].centre());
        if (std::abs(rise - step.rise) > p.max_step_deviation * step.rise ||
            std::abs(run - step.run) > p.max_step_deviation * step.run)
            return false;
    }
    const Eigen::Vector2d d = edges.back().direction();
    for (const LineSegment& e : edges)
        if (std::abs(e.direction().dot(d)) < cos_turn) return false;
    return true;
}

/// Points around one tread of the flight: `on` at `z` within tread_dz in the window
/// [s_lo, s_hi] along `up` from `c` and within `half` of it along the edge, `other` at `z_other`
/// there, `above` higher than z + above_dz.
struct TreadWindow {
    int on = 0, other = 0, above = 0;
    double t_min = 1e9, t_max = -1e9;
    double spread() const { return on > 0 ? t_max - t_min : 0.0; }
};

TreadWindow countTread(const PointCloud& cloud, const Eigen::Vector2d& c, const Eigen::Vector2d& u,
                       const Eigen::Vector2d& up, double half, double s_lo, double s_hi, double z,
                       double z_other, const FlightContinuationParams& p) {
    TreadWindow w;
    for (const Eigen::Vector3f& q : cloud) {
        if (!q.allFinite()) continue;
        const Eigen::Vector2d d(q.x() - c.x(), q.y() - c.y());
        const double s = up.dot(d), t = u.dot(d);
        if (s < s_lo || s > s_hi || std::abs(t) > half) continue;
        if (std::abs(q.z() - z) <= p.tread_dz_m) {
            ++w.on;
            w.t_min = std::min(w.t_min, t);
            w.t_max = std::max(w.t_max, t);
        } else if (std::abs(q.z() - z_other) <= p.tread_dz_m) {
            ++w.other;
        } else if (q.z() > z + p.above_dz_m) {
            ++w.above;
        }
    }
    return w;
}

/// The window shows a tread: enough points spread along the edge, more than at the other level
/// (a platform, or the floor) and hardly any above it (a wall, a box).
bool showsTread(const TreadWindow& w, double half, const FlightContinuationParams& p) {
    return w.on >= p.min_points && w.on > w.other && 4 * w.above <= w.on &&
           w.spread() >= p.min_spread_fraction * 2.0 * half;
}

/// Float bounds (FlightPoints.h) around a strip (distance s along `up` in [s_lo, s_hi] from `c`,
/// |t| along `u` at most `half`) and heights [z_lo, z_hi], padded by a centimetre: a point outside
/// them is outside the strip (most of a cloud), one inside is tested exactly.
FloatBounds stripBox(const Eigen::Vector2d& c, const Eigen::Vector2d& up, const Eigen::Vector2d& u,
                     double s_lo, double s_hi, double half, double z_lo, double z_hi) {
    constexpr double kPad = 0.01;  // [m] far more than float rounding at 100 m
    Eigen::Vector2d lo = c + s_lo * up, hi = lo;
    for (const double a : {s_lo, s_hi})
        for (const double b : {-half, half}) {
            lo = lo.cwiseMin(c + a * up + b * u);
            hi = hi.cwiseMax(c + a * up + b * u);
        }
    const auto f = [](double v) { return static_cast<float>(v); };
    return {{f(lo.x() - kPad), f(lo.y() - kPad), f(z_lo - kPad)},
            {f(hi.x() + kPad), f(hi.y() + kPad), f(z_hi + kPad)}};
}

}  // namespace

bool isRegularStraightChain(const std::vector<LineSegment>& edges,
                            const FlightContinuationParams& p) {
    if (edges.size() < 2) return false;
    const ChainStep step = chainStep(edges);
    return step.rise > 0.0 && step.run > 0.0 && regularStraightChain(edges, step, p);
}

bool treadAboveLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                        const FlightContinuationParams& p) {
    if (!isRegularStraightChain(edges, p)) return false;
    const ChainStep step = chainStep(edges);
    const LineSegment& last = edges.back();
    const double half = 0.5 * last.length() * (1.0 - 2.0 * p.end_fraction);
    const TreadWindow w =
        countTread(cloud, last.centre(), last.direction(), step.up, half, p.from_runs * step.run,
                   p.to_runs * step.run, last.z + step.rise, last.z, p);
    return showsTread(w, half, p);
}

bool riserAboveLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                        const FlightContinuationParams& p) {
    if (!isRegularStraightChain(edges, p)) return false;
    const ChainStep step = chainStep(edges);
    const LineSegment& last = edges.back();
    const Eigen::Vector2d c = last.centre(), u = last.direction();
    const double half = 0.5 * last.length() * (1.0 - 2.0 * p.end_fraction);
    const double s_lo = p.riser_from_runs * step.run, s_hi = p.riser_to_runs * step.run;
    const double s_beyond = s_hi + p.riser_beyond_runs * step.run;
    // The strip looked at starts at the tread behind the last edge (or at the window, if nearer).
    const double s_first = std::min(s_lo, p.riser_tread_from_runs * step.run);
    const double tread_dz_hi = p.riser_from_rises * step.rise;  // below the window's heights
    // The window's points (height above the last edge, place along it), the tread's heights.
    struct WindowPoint {
        double dz, s, t;
    };
    std::vector<WindowPoint> window;
    std::vector<double> tread, beyond;
    const FloatBounds box = stripBox(c, step.up, u, s_first, s_beyond, half, last.z - p.tread_dz_m,
                                     std::numeric_limits<double>::max());
    for (const Eigen::Vector3f& q : cloud) {
        if (!box.mayContain(q)) continue;
        const Eigen::Vector2d d(q.x() - c.x(), q.y() - c.y());
        const double s = step.up.dot(d), t = u.dot(d);
        if (s < s_first || s > s_beyond || std::abs(t) > half) continue;
        const double dz = q.z() - last.z;
        if (s < s_lo) {
            if (dz >= -p.tread_dz_m && dz < tread_dz_hi) tread.push_back(dz);
            continue;
        }
        if (s > s_hi) {
            beyond.push_back(dz);
            continue;
        }
        window.push_back({dz, s, t});
    }
    // The next riser rises from the tread behind the last edge: where that tread is seen a little
    // above the edge (an edge read low on its riser: a two-step stage's platform edge 3 cm under
    // the platform, negatives of seed 26026), the window's heights start above the tread, else
    // above the edge.
    double base = 0.0;
    if (static_cast<int>(tread.size()) >= p.min_points) {
        // Its lower quartile: debris stands on a tread.
        const auto q = tread.begin() + static_cast<std::ptrdiff_t>(tread.size() / 4);
        std::nth_element(tread.begin(), q, tread.end());
        if (*q > p.riser_tread_min_raise_rises * step.rise) base = *q;  // else the edge's noise
    }
    const double z_lo = base + p.riser_from_rises * step.rise;
    const double z_hi = base + p.riser_to_rises * step.rise;
    int on = 0, level = 0, above = 0;
    double t_min = 1e9, t_max = -1e9;
    for (const WindowPoint& w : window) {
        if (w.dz >= z_lo && w.dz <= z_hi) {
            ++on;
            t_min = std::min(t_min, w.t);
            t_max = std::max(t_max, w.t);
        } else if (std::abs(w.dz) <= p.tread_dz_m && w.s > step.run + p.tread_dz_m) {
            ++level;
        } else if (w.dz > step.rise + p.above_dz_m) {
            ++above;
        }
    }
    int flat_beyond = 0;
    for (const double dz : beyond) flat_beyond += dz >= z_lo && dz <= z_hi;
    return on >= p.min_points && on > level && on > 2 * flat_beyond && 4 * above <= on &&
           t_max - t_min >= p.min_spread_fraction * 2.0 * half;
}

bool treadBelowFirstEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                         double floor_z, const FlightContinuationParams& p) {
    if (!isRegularStraightChain(edges, p)) return false;
    const ChainStep step = chainStep(edges);
    const LineSegment& first = edges.front();
    // The first edge two rises above the floor: one step below it is missing.
    if (std::abs(first.z - floor_z - 2.0 * step.rise) > p.tread_dz_m) return false;
    const double half = 0.5 * first.length() * (1.0 - 2.0 * p.end_fraction);
    // The step's tread lies between its nosing (one run in front) and the first edge's riser:
    // the window mirrors the one above the last edge.
    const TreadWindow w = countTread(cloud, first.centre(), first.direction(), step.up, half,
                                     -(p.to_runs - 1.0) * step.run, -(p.from_runs - 1.0) * step.run,
                                     first.z - step.rise, floor_z, p);
    return showsTread(w, half, p);
}

bool floorNosingAbovePit(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                         double floor_z, const FlightContinuationParams& p) {
    if (!isRegularStraightChain(edges, p)) return false;
    const ChainStep step = chainStep(edges);
    const LineSegment& first = edges.front();
    if (std::abs(first.z - floor_z - step.rise) > p.tread_dz_m) return false;
    const double half = 0.5 * first.length() * (1.0 - 2.0 * p.end_fraction);
    const TreadWindow w =
        countTread(cloud, first.centre(), first.direction(), step.up, half, -p.to_runs * step.run,
                   -p.from_runs * step.run, floor_z - step.rise, floor_z, p);
    return showsTread(w, half, p);
}

namespace {

/// No point at or above `min_z` in the window one step beyond the last edge of a regular chain.
bool emptyBeyondLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                         double min_z, const FlightContinuationParams& p) {
    if (!isRegularStraightChain(edges, p)) return false;
    const ChainStep step = chainStep(edges);
    const LineSegment& last = edges.back();
    const Eigen::Vector2d c = last.centre(), u = last.direction();
    const double half = 0.5 * last.length() * (1.0 - 2.0 * p.end_fraction);
    const double s_lo = p.from_runs * step.run, s_hi = p.to_runs * step.run;
    for (const Eigen::Vector3f& q : cloud) {
        if (!q.allFinite() || q.z() < min_z) continue;
        const Eigen::Vector2d d(q.x() - c.x(), q.y() - c.y());
        const double s = step.up.dot(d);
        if (s >= s_lo && s <= s_hi && std::abs(u.dot(d)) <= half) return false;
    }
    return true;
}

}  // namespace

bool unseenBeyondLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                          const FlightContinuationParams& p) {
    return !edges.empty() && emptyBeyondLastEdge(cloud, edges, edges.back().z - p.tread_dz_m, p);
}

bool nothingBeyondLastEdge(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           const FlightContinuationParams& p) {
    return emptyBeyondLastEdge(cloud, edges, -std::numeric_limits<double>::infinity(), p);
}

bool startsFromRaisedLanding(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                             double floor_z, const FlightContinuationParams& p) {
    if (!isRegularStraightChain(edges, p)) return false;
    const ChainStep step = chainStep(edges);
    const LineSegment& first = edges.front();
    const double landing_z = first.z - step.rise;
    if (landing_z - floor_z < p.min_landing_height_m) return false;
    const double half = 0.5 * first.length() * (1.0 - 2.0 * p.end_fraction);
    const TreadWindow w = countTread(cloud, first.centre(), first.direction(), step.up, half,
                                     -(p.to_runs - 1.0) * step.run, -(p.from_runs - 1.0) * step.run,
                                     landing_z, floor_z, p);
    return showsTread(w, half, p);
}

namespace {

/// [m] distance in the vertical plane up the chain from (s, z) to the stair profile of `edges`
/// (edge k at s = edge_s[k]): tread k at its edge's height from edge_s[k] on, the risers below
/// edges k and k + 1 (the first one a rise high). The point lies in [edge_s[k], edge_s[k + 1]].
double stairProfileDistance(const std::vector<LineSegment>& edges,
                            const std::vector<double>& edge_s, std::size_t k, double s, double z,
                            double rise) {
    const auto riser = [&](std::size_t j) {  // the riser under edge j
        const double top = edges[j].z, bottom = j > 0 ? edges[j - 1].z : top - rise;
        const double dz = z > top ? z - top : (z < bottom ? bottom - z : 0.0);
        return std::hypot(s - edge_s[j], dz);
    };
    double d = std::min(std::abs(z - edges[k].z), riser(k));
    if (k + 1 < edges.size()) d = std::min(d, riser(k + 1));
    return d;
}

}  // namespace

bool treadsRiseAlongTheRun(const PointCloud& cloud, const std::vector<LineSegment>& edges,
                           const FlightContinuationParams& p) {
    if (edges.size() < 2) return false;
    const ChainStep step = chainStep(edges);
    if (step.rise <= 0.0 || step.run <= 0.0) return false;
    const LineSegment& first = edges.front();
    const Eigen::Vector2d c = first.centre(), u = first.direction();
    const double half = 0.5 * first.length() * (1.0 - 2.0 * p.end_fraction);
    std::vector<double> edge_s;  // each edge's distance up the chain from the first
    for (const LineSegment& e : edges) edge_s.push_back(step.up.dot(e.centre() - c));
    const double z_lo = first.z - step.rise, z_hi = edges.back().z + step.rise;
    // The ramp: least-squares line z = a + b s; the stair: the profile its edges make.
    double n = 0, ss = 0, sz = 0, sss = 0, ssz = 0, szz = 0, stair = 0;
    const FloatBounds box = stripBox(c, step.up, u, 0.0, edge_s.back(), half, z_lo, z_hi);
    const std::size_t stride = std::max(1, p.ramp_point_stride);
    for (std::size_t i = 0; i < cloud.size(); i += stride) {
        const Eigen::Vector3f& q = cloud[i];
        if (!box.mayContain(q) || q.z() < z_lo || q.z() > z_hi) continue;
        const Eigen::Vector2d d(q.x() - c.x(), q.y() - c.y());
        const double s = step.up.dot(d);
        if (!(s >= 0.0 && s <= edge_s.back() && std::abs(u.dot(d)) <= half)) continue;
        const double z = q.z() - first.z;
        std::size_t k = 0;
        while (k + 1 < edges.size() && edge_s[k + 1] <= s) ++k;
        const double off = stairProfileDistance(edges, edge_s, k, s, q.z(), step.rise);
        stair += off * off;
        n += 1;
        ss += s;
        sz += z;
        sss += s * s;
        ssz += s * z;
        szz += z * z;
    }
    if (n < p.ramp_min_points) return false;
    const double var_s = sss / n - (ss / n) * (ss / n);
    if (var_s < 1e-6) return false;
    const double cov = ssz / n - (ss / n) * (sz / n), var_z = szz / n - (sz / n) * (sz / n);
    const double ramp_rms = std::sqrt(std::max(0.0, var_z - cov * cov / var_s));
    const double stair_rms = std::sqrt(stair / n);
    return ramp_rms < p.ramp_max_rms_ratio * stair_rms;
}

namespace {

/// The line of `lines` two steps (of `step`) beyond `from`, the nearest to two runs; -1 if none.
int lineTwoStepsBeyond(const std::vector<LineSegment>& lines, const LineSegment& from,
                       const ChainStep& step, const FlightContinuationParams& p) {
    const Eigen::Vector2d d = from.direction();
    const double cos_turn = std::cos(p.max_turn_deg * M_PI / 180.0);
    const auto [lo, hi] = extentAlong(from, d);
    int best = -1;
    double best_off = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const LineSegment& l = lines[k];
        const double dz = l.z - from.z;
        if (dz < p.beyond_min_rises * step.rise || dz > p.beyond_max_rises * step.rise) continue;
        const double behind = step.up.dot(l.centre() - from.centre());
        if (behind < p.beyond_from_runs * step.run || behind > p.beyond_to_runs * step.run)
            continue;
        if (std::abs(l.direction().dot(d)) < cos_turn) continue;
        const auto [l_lo, l_hi] = extentAlong(l, d);
        const double overlap = std::min(hi, l_hi) - std::max(lo, l_lo);
        if (overlap < p.beyond_min_overlap * std::min(from.length(), l.length())) continue;
        const double off = std::abs(behind - 2.0 * step.run);
        if (off < best_off) {
            best_off = off;
            best = static_cast<int>(k);
        }
    }
    return best;
}

}  // namespace

std::vector<int> linesEveryOtherStepBeyond(const std::vector<LineSegment>& lines,
                                           const std::vector<LineSegment>& edges,
                                           const FlightContinuationParams& p) {
    std::vector<int> out;
    if (edges.size() < 3 || !isRegularStraightChain(edges, p)) return out;  // two pairs at least
    const ChainStep step = chainStep(edges);
    const LineSegment* from = &edges.back();
    // Each step goes at least beyond_min_rises rises up: no line is taken twice.
    for (;;) {
        const int k = lineTwoStepsBeyond(lines, *from, step, p);
        if (k < 0) break;
        out.push_back(k);
        from = &lines[k];
    }
    return out;
}

LineSegment nextNosing(const std::vector<LineSegment>& edges) {
    const ChainStep step = chainStep(edges);
    const LineSegment& last = edges.back();
    const Eigen::Vector2d shift = step.run * step.up;
    return unseenNosing(last.start + shift, last.end + shift, last.z + step.rise);
}

LineSegment previousNosing(const std::vector<LineSegment>& edges) {
    const ChainStep step = chainStep(edges);
    const LineSegment& first = edges.front();
    const Eigen::Vector2d shift = -step.run * step.up;
    return unseenNosing(first.start + shift, first.end + shift, first.z - step.rise);
}

}  // namespace stairmap
