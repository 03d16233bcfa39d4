#include "core/SpiralSearch.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "core/MissingNosings.h"
#include "core/UpperMedian.h"

namespace stairmap {
namespace {

constexpr double kDeg = M_PI / 180.0;
/// [m] a nosing's near end may lie this far past the axis (noise at the column)
constexpr double kStraddleTolerance = 0.05;
/// [-] of the step angle: a line's angle tolerance, so that no line is near both helices
constexpr double kMaxShareOfStep = 0.45;

double wrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

/// A line seen from an axis candidate: radii of its ends and its angle around the axis.
struct Radial {
    int index = -1;
    double near = 0.0, far = 0.0;  ///< [m] end distances to the axis
    double phi = 0.0;              ///< [rad] direction from the axis to the far end
    double z = 0.0;
    double rot = 0.0;              ///< [rad] turn about the axis onto the level's nosing (back edges)
};

/// The lines of both drop directions, each with its Hessian normal (cos theta, sin theta) computed
/// once: the pair search asks a line's distance and direction for every axis candidate (sin and
/// cos were a third of its time). distanceTo and direction equal LineSegment's, bit for bit.
class SpiralLines {
  public:
    SpiralLines(const std::vector<LineSegment>& a, const std::vector<LineSegment>& b) {
        lines_ = a;
        lines_.insert(lines_.end(), b.begin(), b.end());
        normals_.reserve(lines_.size());
        for (const LineSegment& l : lines_)
            normals_.emplace_back(std::cos(l.theta), std::sin(l.theta));
    }
    std::size_t size() const { return lines_.size(); }
    const LineSegment& operator[](int i) const { return lines_[i]; }
    const Eigen::Vector2d& normal(int i) const { return normals_[i]; }
    /// LineSegment::distanceTo of line i
    double distanceTo(int i, const Eigen::Vector2d& p) const {
        return p.x() * normals_[i].x() + p.y() * normals_[i].y() - lines_[i].rho;
    }
    /// LineSegment::direction of line i
    Eigen::Vector2d direction(int i) const { return {-normals_[i].y(), normals_[i].x()}; }

  private:
    std::vector<LineSegment> lines_;
    std::vector<Eigen::Vector2d> normals_;
};

/// The line as a wedge nosing of a spiral around `axis`, if it is one (radial, inner end near it).
bool asRadial(const SpiralLines& sl, int index, const Eigen::Vector2d& axis,
              const SpiralSearchParams& p, Radial& out) {
    const LineSegment& l = sl[index];
    if (std::abs(sl.distanceTo(index, axis)) > p.max_axis_offset_m) return false;
    const double ds = (l.start - axis).norm(), de = (l.end - axis).norm();
    const Eigen::Vector2d far_pt = ds > de ? l.start : l.end;
    const Eigen::Vector2d near_pt = ds > de ? l.end : l.start;
    out.far = std::max(ds, de);
    out.near = std::min(ds, de);
    if (out.near > p.max_column_radius_m || out.far < p.min_outer_radius_m) return false;
    const Eigen::Vector2d u = (far_pt - axis) / out.far;
    if ((near_pt - axis).dot(u) < -kStraddleTolerance) return false;  // crosses the axis
    out.phi = std::atan2(u.y(), u.x());
    out.index = index;
    out.z = l.z;
    out.rot = 0.0;
    return true;
}

/// Helix model: angle around the axis = phi0 + omega * (z - z0).
struct Helix {
    Eigen::Vector2d axis = Eigen::Vector2d::Zero();
    double z0 = 0.0, phi0 = 0.0;
    double omega = 0.0;  ///< [rad/m], its sign is the sense of ascent
};

/// Lines on the helix turned by `shift` [rad].
std::vector<Radial> collectInliers(const SpiralLines& sl, const Helix& h, double shift,
                                   const SpiralSearchParams& p) {
    std::vector<Radial> in;
    Radial r;
    for (int k = 0; k < static_cast<int>(sl.size()); ++k) {
        if (!asRadial(sl, k, h.axis, p, r)) continue;
        const double predicted = h.phi0 + h.omega * (r.z - h.z0) + shift;
        if (std::abs(wrapAngle(r.phi - predicted)) <= p.angle_tolerance_deg * kDeg) in.push_back(r);
    }
    return in;
}

/// Unwraps each line's angle against the helix `h`, then fits phi = phi0 + omega (z - z0).
bool fitAngleRate(const std::vector<Radial>& in, Helix& h) {
    double sz = 0, sp = 0, szz = 0, szp = 0;
    const double n = static_cast<double>(in.size());
    for (const Radial& r : in) {
        const double dz = r.z - h.z0;
        const double pred = h.phi0 + h.omega * dz;
        const double phi = pred + wrapAngle(r.phi - pred);
        sz += dz, sp += phi, szz += dz * dz, szp += dz * phi;
    }
    const double den = n * szz - sz * sz;
    if (den < 1e-9) return false;
    h.omega = (n * szp - sz * sp) / den;
    h.phi0 = (sp - h.omega * sz) / n;
    return true;
}

/// Least-squares axis (the point nearest to all inlier lines) and helix rate through it.
bool refitHelix(const SpiralLines& sl, const std::vector<Radial>& in, Helix& h) {
    Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    for (const Radial& r : in) {
        const LineSegment& l = sl[r.index];
        const Eigen::Vector2d& n = sl.normal(r.index);
        a += n * n.transpose();
        b += n * l.rho;
    }
    if (std::abs(a.determinant()) < 1e-6) return false;
    h.axis = a.ldlt().solve(b);
    return fitAngleRate(in, h);
}

/// One seen level: the highest inlier line at that height (a riser hit reads low).
std::vector<Radial> levelsOf(std::vector<Radial> in, double tolerance) {
    std::sort(in.begin(), in.end(), [](const Radial& a, const Radial& b) { return a.z < b.z; });
    std::vector<Radial> levels;
    for (const Radial& r : in) {
        if (!levels.empty() && r.z - levels.back().z < tolerance) {
            if (r.z > levels.back().z) levels.back() = r;  // a riser hit reads low
            continue;
        }
        levels.push_back(r);
    }
    return levels;
}

/// Levels indexed on the rise r0 from level `ref`: the longest run with at most
/// max_missing_levels unseen between neighbours (levels off the rise by more than the tolerance
/// are left out).
std::vector<std::pair<int, Radial>> indexOnRise(const std::vector<Radial>& levels, double r0,
                                                double ref_z, const SpiralSearchParams& p,
                                                double& misfit) {
    std::vector<std::pair<int, Radial>> best, run;
    double best_misfit = 0.0, run_misfit = 0.0;
    for (const Radial& l : levels) {
        const double idx = (l.z - ref_z) / r0;
        const int k = static_cast<int>(std::lround(idx));
        if (std::abs(idx - k) * r0 > p.height_tolerance_m || (!run.empty() && k == run.back().first))
            continue;
        if (!run.empty() && k - run.back().first > p.max_missing_levels + 1) {
            if (run.size() > best.size()) best = run, best_misfit = run_misfit;
            run.clear(), run_misfit = 0.0;
        }
        run.emplace_back(k, l);
        run_misfit += std::abs(idx - k) * r0;
    }
    if (run.size() > best.size()) best = run, best_misfit = run_misfit;
    misfit = best_misfit;
    return best;
}

/// [m] lowest rise a helix may read (condition 1 less its noise)
double lowestRise(const SpiralSearchParams& p) { return p.min_rise_m - p.low_rise_noise_m; }

/// Condition 1 on a helix of `levels` levels, `seen` of them with a line: a rise read below
/// min_rise_m (within its noise) counts only with few levels put back (SpiralSearchParams).
bool riseOfAStair(double rise, int levels, int seen, const SpiralSearchParams& p) {
    if (rise < lowestRise(p) || rise > p.max_rise_m) return false;
    return rise >= p.min_rise_m || levels - seen <= p.max_put_back_below_min_rise;
}

/// Step index of every level: on the rise (a gap between two levels, or half of it: every other
/// nosing seen) and from the reference level that index the most levels, each unseen level in
/// between counting against (a small rise fits stray levels), then the least misfit. Empty when
/// none fits.
std::vector<std::pair<int, Radial>> indexLevels(const std::vector<Radial>& levels,
                                                const SpiralSearchParams& p, double& rise) {
    constexpr double kMissingWeight = 0.75;  ///< [-] an unseen level costs this much of a seen one
    std::vector<std::pair<int, Radial>> best;
    double best_score = 0.0, best_misfit = 0.0;
    for (std::size_t i = 1; i < levels.size(); ++i) {
        const double g = levels[i].z - levels[i - 1].z;
        for (double r0 : {g, 0.5 * g}) {
            if (r0 < lowestRise(p) - p.height_tolerance_m ||
                r0 > p.max_rise_m + p.height_tolerance_m)
                continue;
            for (const Radial& ref : levels) {
                double misfit = 0.0;
                auto idx = indexOnRise(levels, r0, ref.z, p, misfit);
                if (idx.empty()) continue;
                const int missing = idx.back().first - idx.front().first + 1 - static_cast<int>(idx.size());
                const double score = static_cast<double>(idx.size()) - kMissingWeight * missing;
                if (score > best_score || (score == best_score && misfit < best_misfit))
                    best = std::move(idx), best_score = score, best_misfit = misfit;
            }
        }
    }
    if (best.size() < 2) return {};
    rise = (best.back().second.z - best.front().second.z) / (best.back().first - best.front().first);
    return best;
}

/// The nosing at angle phi around the axis, from radius near to far, at height z (put back).
LineSegment unseenRadialNosing(const Eigen::Vector2d& axis, double phi, double near, double far,
                               double z) {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi));
    return unseenNosing(axis + near * u, axis + far * u, z);
}

/// The line turned by `rot` about the axis (a back edge moved onto its tread's nosing).
LineSegment turned(const LineSegment& l, const Eigen::Vector2d& axis, double rot) {
    if (rot == 0.0) return l;
    const Eigen::Rotation2Dd r(rot);
    LineSegment m = l;
    m.start = axis + r * (l.start - axis);
    m.end = axis + r * (l.end - axis);
    Eigen::Vector2d n = r * Eigen::Vector2d(std::cos(l.theta), std::sin(l.theta));
    if (n.dot(m.start) < 0) n = -n;  // Hessian form: rho >= 0
    m.rho = n.dot(m.start);
    m.theta = std::atan2(n.y(), n.x());
    return m;
}

/// Nosings and back edges. Where the next wedge's top is unseen (above a level LiDAR), a tread's
/// back edge reads as a drop too: a second helix one step angle ahead of the nosings' in the
/// ascent's sense (at height z, the angle of the nosing one rise higher). Of the lines one step
/// ahead of and behind `in`'s helix, the larger group tells which helix `in` is on; back edges are
/// turned back onto their tread's nosing. Empty when `in` gives no rise.
std::vector<Radial> withBackEdges(const SpiralLines& sl, const Helix& h, std::vector<Radial> in,
                                  const SpiralSearchParams& p) {
    double rise = 0.0;
    if (indexLevels(levelsOf(in, p.height_tolerance_m), p, rise).empty()) return {};
    const double step = h.omega * rise;  // nosing k+1's angle - nosing k's
    std::vector<Radial> ahead = collectInliers(sl, h, step, p);
    std::vector<Radial> behind = collectInliers(sl, h, -step, p);
    const bool in_are_back = behind.size() > ahead.size();
    for (Radial& r : in) r.rot = in_are_back ? -step : 0.0;
    for (Radial& r : in_are_back ? behind : ahead) {
        r.rot = in_are_back ? 0.0 : -step;
        in.push_back(r);
    }
    for (Radial& r : in) r.phi += r.rot;
    return in;
}

/// The nosings' helix fitted to nosings and back edges together, a back edge at its tread's
/// height plus one rise (where its angle is the next nosing's): phi = phi0 + omega (z' - z0). The
/// axis is refitted to all their lines. False when the lines do not determine it.
bool refitOnNosingsAndBackEdges(const SpiralLines& sl, const std::vector<Radial>& in, double rise,
                                const SpiralSearchParams& p, Helix& h) {
    Helix g = h;
    if (!refitHelix(sl, in, g)) return false;  // the axis (omega and phi0 refitted below)
    double sz = 0, sp = 0, szz = 0, szp = 0;
    int n = 0;
    Radial about;
    for (const Radial& r : in) {
        if (!asRadial(sl, r.index, g.axis, p, about)) continue;
        const double dz = r.z + (r.rot != 0.0 ? rise : 0.0) - h.z0;
        const double pred = h.phi0 + h.omega * dz;  // unwrap against the helix before
        const double phi = pred + wrapAngle(about.phi - pred);
        sz += dz, sp += phi, szz += dz * dz, szp += dz * phi, ++n;
    }
    const double den = n * szz - sz * sz;
    if (n < 3 || den < 1e-9) return false;
    g.z0 = h.z0;
    g.omega = (n * szp - sz * sp) / den;
    g.phi0 = (sp - g.omega * sz) / n;
    h = g;
    return true;
}

/// A first helix fitted to a mix of nosings and back edges (9 deg tolerance, steps of 15-25 deg)
/// lies between the two and reads too small a step angle, turning some nosings back a step as if
/// they were back edges. Refit on both (each at its own height), give every radial line to the
/// nearer of the two helices, and repeat: the fit settles on the nosings.
std::vector<Radial> settleOnNosings(const SpiralLines& sl, Helix& h, std::vector<Radial> in,
                                    const SpiralSearchParams& p) {
    constexpr int kIterations = 3;
    for (int it = 0; it < kIterations; ++it) {
        double rise = 0.0;
        if (indexLevels(levelsOf(in, p.height_tolerance_m), p, rise).empty()) break;
        Helix g = h;
        if (!refitOnNosingsAndBackEdges(sl, in, rise, p, g)) break;
        const double step = g.omega * rise;
        const double tol = std::min(p.angle_tolerance_deg * kDeg, kMaxShareOfStep * std::abs(step));
        std::vector<Radial> next;
        Radial r;
        for (int k = 0; k < static_cast<int>(sl.size()); ++k) {
            if (!asRadial(sl, k, g.axis, p, r)) continue;
            const double on = wrapAngle(r.phi - (g.phi0 + g.omega * (r.z - g.z0)));
            const double ahead = wrapAngle(on - step);
            if (std::abs(on) <= std::abs(ahead) && std::abs(on) <= tol) r.rot = 0.0;
            else if (std::abs(ahead) <= tol) r.rot = -step;
            else continue;
            r.phi += r.rot;
            next.push_back(r);
        }
        if (next.size() < 3) break;
        h = g;
        in = std::move(next);
    }
    return in;
}

/// The line as an extra level's edge around `axis` (looser than asRadial: its inner part may be
/// hidden by the column), its outer end at the rim, `outer` [m] from the axis.
bool asExtraRadial(const SpiralLines& sl, int index, const Eigen::Vector2d& axis, double outer,
                   const SpiralSearchParams& p, Radial& out) {
    SpiralSearchParams loose = p;
    loose.max_axis_offset_m = p.extra_max_axis_offset_m;
    loose.max_column_radius_m = std::max(p.max_column_radius_m, p.extra_max_inner_share * outer);
    return asRadial(sl, index, axis, loose, out) &&
           std::abs(out.far - outer) <= p.extra_outer_tolerance_m;
}

/// True when the held levels' inner ends stop at one column (within extra_max_inner_spread_m)
/// and their farthest outer end, the rim, is `outer` [m] from the axis.
bool showsColumnAndRim(const std::vector<std::pair<int, Radial>>& levels,
                       const SpiralSearchParams& p, double& outer) {
    double lo = 1e9, hi = 0.0;
    outer = 0.0;
    for (const auto& [k, r] : levels) {
        lo = std::min(lo, r.near), hi = std::max(hi, r.near);
        outer = std::max(outer, r.far);
    }
    return hi - lo <= p.extra_max_inner_spread_m;
}

/// An extra level's candidate line: its level index and how far off its helix it lies [rad].
struct ExtraLine {
    int level = 0;
    double off = 0.0;
    Radial line;
};

/// Lines (not yet used or taken, looser bounds: asExtraRadial, reaching the rim `outer`) on the
/// nosings' helix or the back edges' one at the height of a level in `levels`' numbering that
/// holds no line yet.
std::vector<ExtraLine> extraCandidates(const SpiralLines& sl, const Helix& h,
                                       const std::vector<std::pair<int, Radial>>& levels, double rise,
                                       double outer, const std::vector<char>& skip,
                                       const SpiralSearchParams& p) {
    const double step = h.omega * rise;
    const double tol = std::min(p.angle_tolerance_deg * kDeg, kMaxShareOfStep * std::abs(step));
    const auto& [ref_k, ref] = levels.front();
    std::vector<ExtraLine> out;
    Radial r;
    for (int k = 0; k < static_cast<int>(sl.size()); ++k) {
        if (skip[k] || !asExtraRadial(sl, k, h.axis, outer, p, r)) continue;
        const double t = (r.z - ref.z) / rise;
        const int level = ref_k + static_cast<int>(std::lround(t));
        if (std::abs(t - std::lround(t)) * rise > p.height_tolerance_m) continue;
        if (std::any_of(levels.begin(), levels.end(), [&](const auto& l) { return l.first == level; }))
            continue;
        const double on = wrapAngle(r.phi - (h.phi0 + h.omega * (r.z - h.z0)));
        const double ahead = wrapAngle(on - step);  // on the back edges' helix
        const double off = std::min(std::abs(on), std::abs(ahead));
        if (off > tol) continue;
        r.rot = std::abs(on) <= std::abs(ahead) ? 0.0 : -step;
        r.phi += r.rot;
        out.push_back({level, off, r});
    }
    return out;
}

/// Once `in` holds min_strict_levels levels (too few for a spiral), the levels it leaves empty are
/// filled from extraCandidates, the nearest in angle per level: between two held levels, or next
/// to the lowest or highest one (repeatedly, a close view's column hides several in a row). The
/// axis and helix stay the strict lines' own, so extra lines alone never make a spiral.
std::vector<Radial> withExtraLevels(const SpiralLines& sl, const Helix& h, std::vector<Radial> in,
                                    const std::vector<char>& used, const SpiralSearchParams& p) {
    double rise = 0.0;
    auto levels = indexLevels(levelsOf(in, p.height_tolerance_m), p, rise);
    // Where the strict lines hold a spiral of their own, its levels and rise stand (filling
    // them too changed rise/run on dev/dev2 both ways, no recall gained).
    const int held = static_cast<int>(levels.size());
    double outer = 0.0;
    if (held < p.min_strict_levels || held >= p.min_seen_levels) return in;
    if (!showsColumnAndRim(levels, p, outer)) return in;
    std::vector<char> skip = used;
    for (const Radial& r : in) skip[r.index] = 1;
    const auto byOff = [](const ExtraLine& a, const ExtraLine& b) { return a.off < b.off; };
    for (bool added = true; added;) {
        added = false;
        auto cand = extraCandidates(sl, h, levels, rise, outer, skip, p);
        std::sort(cand.begin(), cand.end(), byOff);
        for (const ExtraLine& c : cand) {
            const int lo = levels.front().first, hi = levels.back().first;
            if (c.level < lo - 1 || c.level > hi + 1) continue;  // no gap outside the held span
            const auto held_here = [&](const auto& l) { return l.first == c.level; };
            if (std::any_of(levels.begin(), levels.end(), held_here)) continue;  // a nearer one took it
            levels.emplace_back(c.level, c.line);
            std::sort(levels.begin(), levels.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
            in.push_back(c.line);
            skip[c.line.index] = 1;
            added = true;
        }
    }
    return in;
}

/// Whether every gap between two seen levels turns by as many steps as it rises (within
/// `tolerance` steps), the step being the median turn between neighbouring seen levels. A helix
/// through nosings below and a tread's back edges above (each one step ahead of its nosing) reads
/// too large a step angle, puts an unseen level back between the two and indexes every back edge
/// at its own height but one nosing's angle further on: across that gap it turns one step more
/// than it rises (dev5 r1113: 98.8 deg over two levels of 32.5 deg). True when fewer than two
/// pairs of neighbouring levels are seen.
bool gapsTurnAsTheyRise(const std::vector<std::pair<int, Radial>>& idx, double tolerance) {
    std::vector<double> turns;
    for (std::size_t i = 1; i < idx.size(); ++i)
        if (idx[i].first - idx[i - 1].first == 1)
            turns.push_back(wrapAngle(idx[i].second.phi - idx[i - 1].second.phi));
    if (turns.size() < 2) return true;
    const double step = upperMedian(turns);
    for (std::size_t i = 1; i < idx.size(); ++i) {
        const int levels = idx[i].first - idx[i - 1].first;
        const double turn = wrapAngle(idx[i].second.phi - idx[i - 1].second.phi);
        if (levels > 1 && std::abs(turn / step - levels) > tolerance) return false;
    }
    return true;
}

/// How many unseen levels lie under a helix's lowest seen one, `first_z` above the floor, down to
/// the floor: 0 when it starts low enough, -1 when it may not start there (too few seen levels,
/// not a whole number of rises above the floor, or too many levels below).
int levelsBelowFirst(double first_z, double rise, int seen, const SpiralSearchParams& p) {
    if (first_z < p.min_first_height_m) return -1;
    if (first_z <= p.max_first_height_m) return 0;
    if (seen < p.high_start_min_seen_levels) return -1;
    const long rises = std::lround(first_z / rise);
    if (rises < 1 || std::abs(first_z - rises * rise) > p.height_tolerance_m) return -1;
    const int below = static_cast<int>(rises) - 1;
    return below <= p.high_start_max_levels_below ? below : -1;
}

/// The spiral of one axis candidate, if its levels make a stair (empty edges otherwise).
SpiralFlight buildFlight(const SpiralLines& sl, const Helix& h, const std::vector<Radial>& in,
                         const SpiralSearchParams& p) {
    SpiralFlight f;
    double rise = 0.0;
    const auto idx = indexLevels(levelsOf(in, p.height_tolerance_m), p, rise);
    if (static_cast<int>(idx.size()) < p.min_seen_levels) return f;
    const int levels = idx.back().first - idx.front().first + 1;
    const double first_z = idx.front().second.z - p.floor_z;
    if (levels < p.min_steps || !riseOfAStair(rise, levels, static_cast<int>(idx.size()), p))
        return f;
    const int below = levelsBelowFirst(first_z, rise, static_cast<int>(idx.size()), p);
    if (below < 0) return f;
    const double step_angle = std::abs(h.omega) * rise;
    if (step_angle < p.min_step_angle_deg * kDeg || step_angle > p.max_step_angle_deg * kDeg) return f;
    if (!gapsTurnAsTheyRise(idx, p.gap_turn_tolerance_steps)) return f;
    std::vector<double> outers;
    double inner = 1e9;
    for (const auto& [k, r] : idx) outers.push_back(r.far), inner = std::min(inner, r.near);
    const double outer = upperMedian(outers);
    const double run = (inner + outer) * std::sin(0.5 * step_angle);  // chord at mid radius
    if (run < p.min_run_m || run > p.max_run_m) return f;
    const Radial& lowest = idx.front().second;
    for (int k = below; k >= 1; --k) {  // levels under the lowest seen one: on the helix
        const double dz = -k * rise;
        f.edges.push_back(unseenRadialNosing(h.axis, lowest.phi + lowest.rot + h.omega * dz,
                                             lowest.near, lowest.far, lowest.z + dz));
    }
    for (std::size_t i = 0; i < idx.size(); ++i) {
        if (i > 0) {  // levels between two seen ones: on the helix, radii interpolated
            const auto& [ka, a] = idx[i - 1];
            const auto& [kb, b] = idx[i];
            const double dphi = wrapAngle(b.phi - a.phi);
            for (int k = ka + 1; k < kb; ++k) {
                const double t = static_cast<double>(k - ka) / (kb - ka);
                f.edges.push_back(unseenRadialNosing(h.axis, a.phi + t * dphi, a.near + t * (b.near - a.near),
                                               a.far + t * (b.far - a.far), a.z + t * (b.z - a.z)));
            }
        }
        const Radial& r = idx[i].second;
        f.edges.push_back(turned(sl[r.index], h.axis, r.rot));
    }
    f.axis = h.axis;
    f.outer_radius_m = outer;
    f.inner_radius_m = inner;
    f.step_angle_rad = step_angle;
    f.run_m = run;
    f.seen_levels = static_cast<int>(idx.size());
    return f;
}

/// The helix through two lines' angles around h.axis (phi0 and z0 at `ra`), if it turns fast
/// enough to be a spiral's (half the minimum step angle per minimum rise).
bool helixThrough(const Radial& ra, const Radial& rb, const SpiralSearchParams& p, Helix& h) {
    h.z0 = ra.z;
    h.phi0 = ra.phi;
    h.omega = wrapAngle(rb.phi - ra.phi) / (rb.z - ra.z);
    return std::abs(h.omega) * lowestRise(p) >= p.min_step_angle_deg * kDeg * 0.5;
}

/// Axis candidate of a pair of lines: their intersection, when both are radial about it.
bool pairHelix(const SpiralLines& sl, int i, int j, const SpiralSearchParams& p, Helix& h) {
    const LineSegment& a = sl[i];
    const LineSegment& b = sl[j];
    const Eigen::Vector2d da = sl.direction(i), db = sl.direction(j);
    const double cross = da.x() * db.y() - da.y() * db.x();
    if (std::abs(cross) < std::sin(p.min_step_angle_deg * kDeg)) return false;  // parallel
    const Eigen::Vector2d w = b.start - a.start;
    const double t = (w.x() * db.y() - w.y() * db.x()) / cross;
    h.axis = a.start + t * da;
    Radial ra, rb;
    if (!asRadial(sl, i, h.axis, p, ra) || !asRadial(sl, j, h.axis, p, rb)) return false;
    return helixThrough(ra, rb, p, h);
}

/// The spiral through the pair (i, j), with the lines it uses (empty edges when none). Where it
/// has too few seen levels and `few` is given, the spiral of p.few_seen_levels goes there; where
/// it is none and `glimpse` is given, its axis goes there if it holds more seen levels.
SpiralFlight spiralOfPair(const SpiralLines& sl, int i, int j, const std::vector<char>& used,
                          const SpiralSearchParams& p, std::vector<Radial>& in, SpiralFlight* few,
                          SpiralGlimpse* glimpse) {
    Helix h;
    if (!pairHelix(sl, i, j, p, h)) return {};
    in = collectInliers(sl, h, 0.0, p);
    if (in.size() < 3 || !refitHelix(sl, in, h)) return {};
    in = withBackEdges(sl, h, collectInliers(sl, h, 0.0, p), p);
    if (!in.empty()) in = settleOnNosings(sl, h, std::move(in), p);
    in.erase(std::remove_if(in.begin(), in.end(), [&](const Radial& r) { return used[r.index]; }),
             in.end());
    in = withExtraLevels(sl, h, std::move(in), used, p);
    SpiralFlight f = buildFlight(sl, h, in, p);
    // (levels are at most the lines: most failing pairs skip the count)
    if (f.edges.empty() && glimpse && static_cast<int>(in.size()) > glimpse->seen_levels) {
        const int seen = static_cast<int>(levelsOf(in, p.height_tolerance_m).size());
        if (seen > glimpse->seen_levels) *glimpse = {h.axis, seen};
    }
    if (f.edges.empty() && few) {
        SpiralSearchParams fewer = p;
        fewer.min_seen_levels = p.few_seen_levels;
        fewer.max_missing_levels = p.few_max_missing_levels;
        fewer.high_start_min_seen_levels = std::numeric_limits<int>::max();
        *few = buildFlight(sl, h, in, fewer);
    }
    return f;
}

/// Best spiral among the lines not yet used (empty edges when none), trying every pair of lines one
/// to two rises apart with `ofPair(i, j, in, few)` (it returns the spiral through the pair and the
/// lines it uses, and where `few` is given, a spiral of fewer seen levels there). The best of
/// those goes to `best_few` when given.
template <typename OfPair>
SpiralFlight bestOfPairs(const SpiralLines& sl, const std::vector<char>& used,
                         const SpiralSearchParams& p, std::vector<int>& inliers, OfPair&& ofPair,
                         SpiralFlight* best_few = nullptr) {
    SpiralFlight best;
    std::size_t best_few_lines = 0;
    const int n = static_cast<int>(sl.size());
    std::vector<char> explored(n, 0);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double dz = sl[j].z - sl[i].z;
            if (used[i] || used[j] || (explored[i] && explored[j])) continue;
            if (p.pair_lines > 0 && i >= p.pair_lines && j >= p.pair_lines) continue;
            if (dz < lowestRise(p) - p.height_tolerance_m || dz > 2.0 * p.max_rise_m) continue;
            std::vector<Radial> in;
            SpiralFlight few;
            SpiralFlight f = ofPair(i, j, in, best_few ? &few : nullptr);
            // More levels, then more seen ones, then more lines on the helices: a helix through
            // nosings below and back edges above (its step angle too large) can index as many
            // levels as the true one but holds fewer lines (dev r0245: 12 against 13).
            const auto rank = [](const SpiralFlight& s, std::size_t lines) {
                return std::make_tuple(s.edges.size(), s.seen_levels, lines);
            };
            if (f.edges.empty()) {  // its pairs are explored again: a spiral may still hold them
                if (!few.edges.empty() && rank(few, in.size()) > rank(*best_few, best_few_lines)) {
                    *best_few = std::move(few);
                    best_few_lines = in.size();
                }
                continue;
            }
            for (const Radial& r : in) explored[r.index] = 1;  // their other pairs: the same axis
            if (rank(f, in.size()) > rank(best, inliers.size())) {
                best = std::move(f);
                inliers.clear();
                for (const Radial& r : in) inliers.push_back(r.index);
            }
        }
    }
    return best;
}

/// Best spiral of radial nosings among the lines not yet used (empty edges when none), and the
/// best of p.few_seen_levels seen levels into `few` and the glimpse into `glimpse` when given.
SpiralFlight bestSpiral(const SpiralLines& sl, const std::vector<char>& used,
                        const SpiralSearchParams& p, std::vector<int>& inliers, SpiralFlight* few,
                        SpiralGlimpse* glimpse) {
    return bestOfPairs(
        sl, used, p, inliers,
        [&](int i, int j, std::vector<Radial>& in, SpiralFlight* few_here) {
            return spiralOfPair(sl, i, j, used, p, in, few_here, glimpse);
        },
        few);
}

// ---- Spirals seen by their treads' outer rims -------------------------------------------------
// A tread's outer edge is an arc of radius R from its nosing's angle to the next one's; seen as a
// line it is the chord, whose foot (the point nearest the axis) lies half a step angle ahead of
// the nosing in the ascent's sense, R cos(step / 2) from the axis. The feet make a helix.

/// The line as a rim chord around `axis`: Radial with phi the foot's angle, far its distance.
bool asRim(const SpiralLines& sl, int index, const Eigen::Vector2d& axis, double max_half_chord,
           const SpiralSearchParams& p, Radial& out) {
    const LineSegment& l = sl[index];
    const Eigen::Vector2d d = sl.direction(index);
    const Eigen::Vector2d foot = l.start + (axis - l.start).dot(d) * d;
    out.far = (foot - axis).norm();
    if (out.far < p.min_outer_radius_m || out.far > p.max_rim_distance_m) return false;
    const double reach = std::max(std::abs((l.start - foot).dot(d)), std::abs((l.end - foot).dot(d)));
    if (reach > max_half_chord + p.rim_chord_tolerance_m) return false;  // not on the chord
    const Eigen::Vector2d u = (foot - axis) / out.far;
    out.phi = std::atan2(u.y(), u.x());
    out.near = 0.0;
    out.index = index;
    out.z = l.z;
    out.rot = 0.0;
    return true;
}

/// Half a chord of `step` [rad] at distance `dist` from the axis.
double halfChord(double dist, double step) { return dist * std::tan(0.5 * std::abs(step)); }

/// Rim chords at the common distance `dist` whose feet lie on the helix.
std::vector<Radial> collectRims(const SpiralLines& sl, const Helix& h, double dist, double max_step,
                                const SpiralSearchParams& p) {
    std::vector<Radial> in;
    Radial r;
    for (int k = 0; k < static_cast<int>(sl.size()); ++k) {
        if (!asRim(sl, k, h.axis, halfChord(dist, max_step), p, r)) continue;
        if (std::abs(r.far - dist) > p.rim_distance_tolerance_m) continue;
        const double predicted = h.phi0 + h.omega * (r.z - h.z0);
        if (std::abs(wrapAngle(r.phi - predicted)) <= p.rim_angle_tolerance_deg * kDeg) in.push_back(r);
    }
    return in;
}

/// Axis and common distance fitted to the chords: each line's signed distance from the axis,
/// n.a - rho, is s R with s its current side (three unknowns, linear). False when degenerate.
bool refitRimAxis(const SpiralLines& sl, const std::vector<Radial>& in, Helix& h, double& dist) {
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (const Radial& r : in) {
        const LineSegment& l = sl[r.index];
        const Eigen::Vector2d& n = sl.normal(r.index);
        const double side = n.dot(h.axis) - l.rho < 0 ? -1.0 : 1.0;
        const Eigen::Vector3d row(n.x(), n.y(), -side);
        a += row * row.transpose();
        b += row * l.rho;
    }
    if (std::abs(a.determinant()) < 1e-6) return false;
    const Eigen::Vector3d x = a.ldlt().solve(b);
    h.axis = x.head<2>();
    dist = x.z();
    return dist > 0.0;
}

/// Axis candidate of a pair of lines as rim chords: the intersection of their normals through
/// their centres, both chords about equally far from it.
bool rimPairHelix(const SpiralLines& sl, int i, int j, const SpiralSearchParams& p, Helix& h,
                  double& dist) {
    const LineSegment& a = sl[i];
    const LineSegment& b = sl[j];
    const Eigen::Vector2d& na = sl.normal(i);
    const Eigen::Vector2d& nb = sl.normal(j);
    const double cross = na.x() * nb.y() - na.y() * nb.x();
    if (std::abs(cross) < std::sin(0.5 * p.min_step_angle_deg * kDeg)) return false;  // parallel
    const Eigen::Vector2d w = b.centre() - a.centre();
    h.axis = a.centre() + (w.x() * nb.y() - w.y() * nb.x()) / cross * na;
    Radial ra, rb;
    const double max_step = p.max_step_angle_deg * kDeg;
    const double dist_a = std::abs(sl.distanceTo(i, h.axis)),
                 dist_b = std::abs(sl.distanceTo(j, h.axis));
    if (!asRim(sl, i, h.axis, halfChord(dist_a, max_step), p, ra) ||
        !asRim(sl, j, h.axis, halfChord(dist_b, max_step), p, rb))
        return false;
    if (std::abs(ra.far - rb.far) > 2.0 * p.rim_distance_tolerance_m) return false;
    dist = 0.5 * (ra.far + rb.far);
    return helixThrough(ra, rb, p, h);
}

/// The spiral whose rims the pair (i, j) may be, with the lines it uses (empty edges when none).
SpiralFlight rimSpiralOfPair(const SpiralLines& sl, int i, int j, const std::vector<char>& used,
                             const SpiralSearchParams& p, std::vector<Radial>& in) {
    Helix h;
    double dist = 0.0;
    if (!rimPairHelix(sl, i, j, p, h, dist)) return {};
    const double max_step = p.max_step_angle_deg * kDeg;
    in = collectRims(sl, h, dist, max_step, p);
    if (in.size() < 3 || !refitRimAxis(sl, in, h, dist) || !fitAngleRate(in, h)) return {};
    in = collectRims(sl, h, dist, max_step, p);
    in.erase(std::remove_if(in.begin(), in.end(), [&](const Radial& r) { return used[r.index]; }),
             in.end());
    double rise = 0.0;
    const auto idx = indexLevels(levelsOf(in, p.height_tolerance_m), p, rise);
    SpiralFlight f;
    if (static_cast<int>(idx.size()) < p.min_seen_levels) return f;
    const int levels = idx.back().first - idx.front().first + 1;
    const double first_z = idx.front().second.z - p.floor_z;
    if (levels < p.min_steps || !riseOfAStair(rise, levels, static_cast<int>(idx.size()), p))
        return f;
    if (first_z < p.min_first_height_m || first_z > p.max_first_height_m) return f;
    const double step = h.omega * rise;  // signed: the ascent's sense
    if (std::abs(step) < p.min_step_angle_deg * kDeg || std::abs(step) > p.max_step_angle_deg * kDeg)
        return f;
    Radial check;
    for (const auto& [k, r] : idx)  // each seen line within its chord at this step angle
        if (!asRim(sl, r.index, h.axis, halfChord(dist, step), p, check)) return f;
    const double outer = dist / std::cos(0.5 * step);
    const double inner = p.rim_column_radius_m;
    const double run = (inner + outer) * std::sin(0.5 * std::abs(step));
    if (run < p.min_run_m || run > p.max_run_m) return f;
    // Nosings half a step behind their rims' feet, from the assumed column to the rim; levels
    // between two seen ones on the helix.
    const auto nosingAt = [&](double phi, double z, int points) {
        LineSegment l = unseenRadialNosing(h.axis, phi - 0.5 * step, inner, outer, z);
        l.num_points = points;
        return l;
    };
    for (std::size_t n = 0; n < idx.size(); ++n) {
        const auto& [kb, b] = idx[n];
        if (n > 0) {
            const auto& [ka, a] = idx[n - 1];
            const double dphi = wrapAngle(b.phi - a.phi);
            for (int k = ka + 1; k < kb; ++k) {
                const double t = static_cast<double>(k - ka) / (kb - ka);
                f.edges.push_back(nosingAt(a.phi + t * dphi, a.z + t * (b.z - a.z), 0));
            }
        }
        f.edges.push_back(nosingAt(b.phi, b.z, sl[b.index].num_points));
    }
    f.axis = h.axis;
    f.outer_radius_m = outer;
    f.inner_radius_m = inner;
    f.step_angle_rad = std::abs(step);
    f.run_m = run;
    f.seen_levels = static_cast<int>(idx.size());
    return f;
}

/// Best rim-seen spiral among the lines not yet used (empty edges when none).
SpiralFlight bestRimSpiral(const SpiralLines& sl, const std::vector<char>& used,
                           const SpiralSearchParams& p, std::vector<int>& inliers) {
    return bestOfPairs(sl, used, p, inliers,
                       [&](int i, int j, std::vector<Radial>& in, SpiralFlight*) {
                           return rimSpiralOfPair(sl, i, j, used, p, in);
                       });
}

}  // namespace

std::vector<SpiralFlight> findSpirals(const std::vector<LineSegment>& front_drops,
                                      const std::vector<LineSegment>& back_drops,
                                      const SpiralSearchParams& params,
                                      std::vector<SpiralFlight>* few_level,
                                      SpiralGlimpse* glimpse) {
    // a wedge's edges read as either drop, depending on the view
    const SpiralLines sl(front_drops, back_drops);
    std::vector<SpiralFlight> out;
    std::vector<char> used(sl.size(), 0);
    const bool want_few =
        few_level && params.few_seen_levels > 0 && params.few_seen_levels < params.min_seen_levels;
    for (int n = 0; n < params.max_spirals; ++n) {
        std::vector<int> inliers;
        SpiralFlight few;
        SpiralFlight f = bestSpiral(sl, used, params, inliers, want_few ? &few : nullptr, glimpse);
        if (f.edges.empty()) {  // the search over the lines no spiral took
            if (!few.edges.empty()) few_level->push_back(std::move(few));
            break;
        }
        for (int k : inliers) used[k] = 1;
        // The remaining lines (the other drop's copies of the nosings, pieces) may give the same
        // spiral again, better seen: one spiral per footprint, the one with more levels.
        auto same = std::find_if(out.begin(), out.end(), [&](const SpiralFlight& o) {
            return (o.axis - f.axis).norm() < std::min(o.outer_radius_m, f.outer_radius_m);
        });
        if (same == out.end()) out.push_back(std::move(f));
        else if (f.edges.size() > same->edges.size()) *same = std::move(f);
    }
    // Rim views: only where the radial search found nothing (their lines are no nosings).
    if (params.rim_search && out.empty()) {
        std::vector<int> inliers;
        SpiralFlight f = bestRimSpiral(sl, used, params, inliers);
        if (!f.edges.empty()) out.push_back(std::move(f));
    }
    return out;
}

}  // namespace stairmap
