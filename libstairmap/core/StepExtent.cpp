#include "core/StepExtent.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

constexpr double kMinSpreadS = 0.02;  ///< [m] points of a bin spread less along s: no slope
constexpr double kMaxTreadSlope = 0.25;  ///< [-] dz/ds; stairs' stringers slope 0.36-1 (20-45 deg)
/// Bin bits: tread points in the tread window, points above / below it there; points on the
/// nosing line at the tread's height, points above the nosing line.
constexpr std::uint8_t kTread = 1, kAbove = 2, kBelow = 4, kOnNosing = 8, kAboveNosing = 16;

/// One step's tread in its own frame: c = edge centre, u = along the edge (left -> right), n =
/// outward. Lateral bins from t0 record tread points and points above / below the tread.
struct TreadScan {
    Eigen::Vector2d c, u, n;
    Eigen::Vector2d edge_u;  ///< the found edge's own direction (u is the flight's when straight)
    double z = 0.0, s_lo = 0.0, s_hi = 0.0, t0 = 0.0;
    double nosing_band = 0.0;  ///< [m] |s| up to this is on the nosing line
    /// [m] beyond this s, points up to next_front_dz above the tread are the next step's front
    double next_front_s = 1e18, next_front_dz = 0.0;
    std::size_t step = 0;          ///< index in the staircase
    int edge_lo = 0, edge_hi = 0;  ///< bins covered by the found edge
    std::vector<std::uint8_t> bins;  ///< kTread | kAbove | kBelow | kOnNosing | kAboveNosing
    /// per bin, points near the tread's height (within side_dz): their count and the sums that
    /// give the slope of height against s. A tread is flat; a sloped surface beside it (a
    /// stringer's top) crosses the tread's height within the run and is no tread.
    struct Near {
        int on = 0;  ///< of them within tread_dz
        double n = 0, s = 0, ss = 0, z = 0, sz = 0;
    };
    std::vector<Near> near;
    /// The nosing line is hit here at the tread's height, nothing rises above it (a wall or a
    /// column beside the flight would) and the tread window holds no point at all: the step
    /// seen along its nosing only. (A stringer beside the flight puts points in the window.)
    bool onBareNosing(int b) const {
        const std::uint8_t any = kOnNosing | kAboveNosing | kTread | kAbove | kBelow;
        return (bins[b] & any) == kOnNosing && near[b].n == 0;
    }
    bool isStep(int b) const { return isTread(b) || onBareNosing(b); }
    bool isTread(int b) const {
        const Near& q = near[b];
        if (q.on == 0) return false;
        const double var_s = q.ss / q.n - (q.s / q.n) * (q.s / q.n);
        if (var_s < kMinSpreadS * kMinSpreadS) return true;  // one ring: no slope to measure
        const double slope = (q.sz / q.n - (q.s / q.n) * (q.z / q.n)) / var_s;
        return std::abs(slope) < kMaxTreadSlope;
    }
};

constexpr double kMaxAbove = 2.0;  ///< [m] higher points are ceilings, not walls

TreadScan scanOf(const Staircase& s, std::size_t k, const StepExtentParams& p) {
    const StairEdge& e = s.steps[k];
    TreadScan t;
    t.step = k;
    t.c = e.centre().head<2>();
    t.u = (e.end - e.start).head<2>().normalized();
    t.edge_u = t.u;
    t.n = outwardNormal(s, k);
    t.z = e.centre().z();
    const double run = std::max(s.step_depth, 0.1);
    const bool up = s.direction == StairDirection::Ascending;
    t.s_lo = up ? p.tread_from_runs * run : -p.tread_to_runs * run;
    t.s_hi = up ? p.tread_to_runs * run : -p.tread_from_runs * run;
    t.nosing_band = p.nosing_band_runs * run;
    if (up) {  // ascending: the next riser (or open tread's front) stands at s = run
        t.next_front_s = run - p.next_front_margin_m;
        t.next_front_dz = 1.5 * s.step_height;
    }
    const double half = 0.5 * e.length(), reach = p.max_extension_m + p.side_band_m;
    t.t0 = -half - reach;
    t.bins.assign(static_cast<std::size_t>(std::ceil((2 * half + 2 * reach) / p.bin_m)) + 1, 0);
    t.near.assign(t.bins.size(), {});
    t.edge_lo = static_cast<int>((-half - t.t0) / p.bin_m);
    t.edge_hi = static_cast<int>((half - t.t0) / p.bin_m);
    return t;
}

void addPoint(TreadScan& t, const Eigen::Vector3f& q, const StepExtentParams& p) {
    const Eigen::Vector2d d(q.x() - t.c.x(), q.y() - t.c.y());
    const double s = t.n.dot(d);
    if ((s < t.s_lo || s > t.s_hi) && std::abs(s) > t.nosing_band) return;
    const int b = static_cast<int>(std::floor((t.u.dot(d) - t.t0) / p.bin_m));
    if (b < 0 || b >= static_cast<int>(t.bins.size())) return;
    const double dz = q.z() - t.z;
    if (std::abs(s) <= t.nosing_band) {
        if (std::abs(dz) <= p.tread_dz_m) t.bins[b] |= kOnNosing;
        else if (dz > p.side_dz_m && dz < kMaxAbove) t.bins[b] |= kAboveNosing;
    }
    if (s < t.s_lo || s > t.s_hi) return;
    if (std::abs(dz) <= p.side_dz_m) {
        TreadScan::Near& acc = t.near[b];
        acc.n += 1;
        acc.s += s;
        acc.ss += s * s;
        acc.z += dz;
        acc.sz += s * dz;
        if (std::abs(dz) <= p.tread_dz_m) {
            ++acc.on;
            t.bins[b] |= kTread;
        }
    } else if (dz > p.side_dz_m && dz < kMaxAbove) {
        if (!(s > t.next_front_s && dz < t.next_front_dz)) t.bins[b] |= kAbove;
    } else if (dz < -p.side_dz_m) {
        t.bins[b] |= kBelow;
    }
}

/// The scans ordered by their position along the flight, so that a point is offered only to the
/// few whose windows may hold it (a straight flight: one or two instead of all). Along the
/// flight's mean outward normal m, a point q lies in scan k's window [w_lo, w_hi] (in s, tread
/// window and nosing band) only if m.(q - c_k) is within it widened by |n_k - m| |q - c_k|, and
/// |q - c_k| is at most the diagonal of the box holding all windows. Exact: a scan left out
/// would reject the point at its first test (addPoint).
class ScansAlongFlight {
public:
    /// `indexed` false: every scan for every point (the reference).
    ScansAlongFlight(const std::vector<TreadScan>& scans, double box_diagonal, bool indexed) {
        Eigen::Vector2d m = Eigen::Vector2d::Zero();
        for (const TreadScan& t : scans) m += t.n;
        if (!indexed || scans.empty() || m.norm() < 1e-6) {
            all_ = scans.size();  // no common direction: every scan
            return;
        }
        m_ = m.normalized();
        double turn = 0.0;
        w_lo_ = 1e18, w_hi_ = -1e18;
        for (std::size_t k = 0; k < scans.size(); ++k) {
            const TreadScan& t = scans[k];
            turn = std::max(turn, (t.n - m_).norm());
            w_lo_ = std::min(w_lo_, std::min(t.s_lo, -t.nosing_band));
            w_hi_ = std::max(w_hi_, std::max(t.s_hi, t.nosing_band));
            keys_.emplace_back(m_.dot(t.c), k);
        }
        slack_ = turn * box_diagonal + 1e-6;  // 1e-6 m: rounding of the two dot products
        std::sort(keys_.begin(), keys_.end());
    }

    /// Calls f(k) for every scan k whose window may hold q.
    template <typename F>
    void forEachReaching(const Eigen::Vector3f& q, F&& f) const {
        if (keys_.empty()) {
            for (std::size_t k = 0; k < all_; ++k) f(k);
            return;
        }
        const double at = m_.x() * q.x() + m_.y() * q.y();
        const double key_lo = at - w_hi_ - slack_, key_hi = at - w_lo_ + slack_;
        auto it = std::lower_bound(keys_.begin(), keys_.end(), std::make_pair(key_lo, std::size_t{0}));
        for (; it != keys_.end() && it->first <= key_hi; ++it) f(it->second);
    }

private:
    Eigen::Vector2d m_ = Eigen::Vector2d::Zero();
    double w_lo_ = 0.0, w_hi_ = 0.0, slack_ = 0.0;
    std::vector<std::pair<double, std::size_t>> keys_;  ///< (m . c_k, k), sorted
    std::size_t all_ = 0;
};

/// Last tread bin walking from `from` in direction `dir` (+1 / -1): across any hole up to
/// max_gap, and across a longer one up to `open_gap_m` when nothing in it rises above the tread
/// (a sparse or shadowed tread, a nosing seen in dashes; a wall or a box stops the walk after
/// max_gap). A bin where the step is seen on its bare nosing only counts as tread (a far ring
/// may hit a step only there); with an open gap beyond the side band (a straight flight), such
/// a bin resumes the tread on its own after a hole with nothing above.
int walkTread(const TreadScan& t, int from, int dir, double open_gap_m, const StepExtentParams& p) {
    const int max_gap = static_cast<int>(p.max_gap_m / p.bin_m);
    const int long_gap = static_cast<int>(open_gap_m / p.bin_m);
    const bool dashes = open_gap_m > p.side_band_m;
    const int max_steps = static_cast<int>(p.max_extension_m / p.bin_m);
    int last = from, gap = 0;
    bool above = false;
    for (int i = from + dir, n = 0; i >= 0 && i < static_cast<int>(t.bins.size()) && n < max_steps;
         i += dir, ++n) {
        // After a hole the tread resumes only with another tread bin within the next two (not
        // at a stray point, such as where a stringer's top crosses the tread's height), or at a
        // bare nosing's dash when nothing rose above the tread in the hole.
        const auto treadAt = [&](int j) {
            return j >= 0 && j < static_cast<int>(t.bins.size()) && t.isStep(j);
        };
        const bool resumes = gap <= 1 || treadAt(i + dir) || treadAt(i + 2 * dir) ||
                             (dashes && !above && t.onBareNosing(i));
        if (t.isStep(i) && resumes) {
            last = i;
            gap = 0;
            above = false;
            continue;
        }
        above = above || (t.bins[i] & kAbove);
        if (++gap > long_gap || (above && gap > max_gap)) break;
    }
    return last;
}

/// Side at and beyond the last tread bin `end` in direction dir (the last bin may hold a wall's
/// foot at the tread's height together with the wall above it).
StairSide sideBeyond(const TreadScan& t, int end, int dir, const StepExtentParams& p) {
    std::uint8_t seen = 0;
    const int band = static_cast<int>(p.side_band_m / p.bin_m);
    for (int i = end, n = 0; i >= 0 && i < static_cast<int>(t.bins.size()) && n <= band;
         i += dir, ++n)
        seen |= t.bins[i];
    if (seen & kAbove) return StairSide::Wall;
    if (seen & kBelow) return StairSide::Open;
    return StairSide::Unseen;
}

struct SideVotes {
    int wall = 0, open = 0, unseen = 0;
    void add(StairSide s) { ++(s == StairSide::Wall ? wall : s == StairSide::Open ? open : unseen); }
    StairSide result() const {
        if (wall + open < unseen || wall + open == 0) return StairSide::Unseen;
        return wall >= open ? StairSide::Wall : StairSide::Open;
    }
};

/// The tread's measured extent (bins) and what bounds it on either side.
struct Extent {
    int lo = 0, hi = 0;
    StairSide left = StairSide::Unseen, right = StairSide::Unseen;
};

Extent measure(const TreadScan& t, double open_gap_m, const StepExtentParams& p) {
    Extent x;
    x.lo = walkTread(t, t.edge_lo, -1, open_gap_m, p);
    x.hi = walkTread(t, t.edge_hi, +1, open_gap_m, p);
    x.left = sideBeyond(t, x.lo, -1, p);
    x.right = sideBeyond(t, x.hi, +1, p);
    return x;
}

/// Sets the edge to the measured extent (never shorter). The extent ends at the centres of its
/// outermost tread bins, where their points lie on average: their outer boundaries read every
/// step half a bin long at each end (elevation maps' walled flights read 1.6 cm wide in the
/// median; width MAE dev / dev2 / dev3 6.82 / 8.04 / 7.27 -> 6.44 / 7.70 / 6.93 cm, with a quarter
/// bin in from the boundaries 6.59 / 7.83 / 7.04, a whole bin 6.56 / 7.86 / 7.13).
void applyExtent(const TreadScan& t, const Extent& x, const StepExtentParams& p, StairEdge& e) {
    const Eigen::Vector3d c = e.centre(), u(t.edge_u.x(), t.edge_u.y(), 0.0);
    if (x.lo < t.edge_lo) e.start = c + (t.t0 + (x.lo + 0.5) * p.bin_m) * u;
    if (x.hi > t.edge_hi) e.end = c + (t.t0 + (x.hi + 0.5) * p.bin_m) * u;
}

/// Across the flight: lateral positions in one frame for all steps (the steps' own edge
/// directions differ by the fits' noise).
struct AcrossFlight {
    Eigen::Vector2d v, o;
    double at(const TreadScan& t, double bin_pos, double bin_m) const {
        return v.dot(t.c + (t.t0 + bin_pos * bin_m) * t.u - o);
    }
};

/// Side `dir` (-1 left, +1 right), where the steps saw it unseen: if a wall or railing is seen
/// beyond the hole on enough of them at one place across the flight (robust: the median), the
/// position of the flight's side there; NaN if none.
double boundAcrossHole(const std::vector<TreadScan>& scans, const std::vector<Extent>& ext, int dir,
                       const AcrossFlight& across, const StepExtentParams& p) {
    const int max_bins = static_cast<int>(p.max_bridge_m / p.bin_m);
    std::vector<double> at;
    int unseen = 0;
    for (std::size_t k = 0; k < scans.size(); ++k) {
        if ((dir < 0 ? ext[k].left : ext[k].right) != StairSide::Unseen) continue;
        ++unseen;
        const TreadScan& t = scans[k];
        const int end = dir < 0 ? ext[k].lo : ext[k].hi;
        for (int i = end + dir, n = 0;
             i >= 0 && i < static_cast<int>(t.bins.size()) && n < max_bins; i += dir, ++n) {
            if (t.bins[i] & kBelow) break;  // a drop: no wall bounds the tread here
            if (t.bins[i] & kAbove) {
                at.push_back(across.at(t, dir < 0 ? i + 1 : i, p.bin_m));
                break;
            }
        }
    }
    if (at.empty() || static_cast<int>(at.size()) < p.min_bridge_steps) return std::nan("");
    std::nth_element(at.begin(), at.begin() + at.size() / 2, at.end());
    const double median = at[at.size() / 2];
    const auto agree = std::count_if(
        at.begin(), at.end(), [&](double a) { return std::abs(a - median) <= p.bridge_agree_m; });
    if (agree < p.min_bridge_steps || 2 * agree < unseen) return std::nan("");
    return median;
}

/// Lengthens the edge of scan t on side dir to lateral position `bound` (never shortens it).
void extendTo(const TreadScan& t, int dir, double bound, const AcrossFlight& across, StairEdge& e) {
    const double along = across.v.dot(t.u);
    if (std::abs(along) < 0.5) return;  // a step turned far from the flight's line (a spiral)
    const Eigen::Vector3d c = e.centre(), u(t.u.x(), t.u.y(), 0.0);
    const double tc = (bound - across.v.dot(c.head<2>() - across.o)) / along;  // along u from c
    if (dir < 0 && tc < (e.start - c).dot(u)) e.start = c + tc * u;
    if (dir > 0 && tc > (e.end - c).dot(u)) e.end = c + tc * u;
}

/// Sides no step saw bounded but a wall or railing beyond a hole bounds (boundAcrossHole): marked
/// Wall, every step lengthened to it. Returns whether any side was.
bool boundSidesAcrossHoles(const std::vector<TreadScan>& scans, const std::vector<Extent>& ext,
                           const StepExtentParams& p, Staircase& stairs) {
    Eigen::Vector2d v = Eigen::Vector2d::Zero();
    for (const TreadScan& t : scans) v += t.u;
    if (scans.empty() || v.norm() < 1e-6) return false;
    const AcrossFlight across{v.normalized(), scans.front().c};
    bool any = false;
    for (int dir : {-1, +1}) {
        StairSide& side = dir < 0 ? stairs.left_side : stairs.right_side;
        if (side != StairSide::Unseen) continue;
        const double bound = boundAcrossHole(scans, ext, dir, across, p);
        if (std::isnan(bound)) continue;
        side = StairSide::Wall;
        any = true;
        for (const TreadScan& t : scans) extendTo(t, dir, bound, across, stairs.steps[t.step]);
    }
    return any;
}

/// A turning flight's width from its measured steps' `widths` (the steps of one flight are equally
/// wide). With a side unseen every step reads at most its true width (its end out of view, hidden
/// by the floor's edge or a nearer step): the widest step is the best estimate. With both sides
/// bounded the extents end at the walls or open edges; a shorter one lost part of its tread to a
/// gap in a far row, a longer one ran onto a surface at tread height beside the flight: the upper
/// quartile. (Dev set: width MAE 10.9 -> 7.6 cm, with both sides bounded 6.2 -> 5.5 cm; the
/// widest step for bounded flights too gave 6.2 cm there, the upper quartile for all 8.8 cm.)
double flightWidth(std::vector<double> widths, const Staircase& stairs) {
    std::sort(widths.begin(), widths.end());
    if (stairs.left_side == StairSide::Unseen || stairs.right_side == StairSide::Unseen)
        return widths.back();
    return widths[(widths.size() * 3) / 4];
}

/// On a straight flight (every edge within max_dev of the flight's common direction) each tread
/// is scanned along that common direction: one edge's fit off by a few degrees would otherwise
/// tilt its window across the run, so that near its ends the next step's nosing falls into it
/// and reads as a wall (dev2 r0079: edges 3 deg off, 1.49 m read for 2.2 m).
bool alignStraightFlight(std::vector<TreadScan>& scans, double max_dev_rad) {
    if (scans.size() < 2 || !(max_dev_rad > 0.0)) return false;
    Eigen::Vector2d m = Eigen::Vector2d::Zero();
    for (const TreadScan& t : scans) m += (t.u.dot(scans.front().u) >= 0 ? 1.0 : -1.0) * t.u;
    if (m.norm() < 1e-6) return false;
    m.normalize();
    const double min_cos = std::cos(max_dev_rad);
    for (const TreadScan& t : scans)
        if (std::abs(t.u.dot(m)) < min_cos) return false;  // turning: a spiral, a winder
    for (TreadScan& t : scans) {
        const Eigen::Vector2d u = t.u.dot(m) >= 0 ? m : Eigen::Vector2d(-m);
        const Eigen::Vector2d n(-u.y(), u.x());
        t.n = n.dot(t.n) >= 0 ? n : Eigen::Vector2d(-n);
        t.u = u;
    }
    return true;
}

/// [m] The width of a straight flight from its two sides measured apart, in one frame across the
/// flight: each side may be seen to its end on other steps than the other side (width MAE
/// dev / dev2 / dev3 6.44 / 7.70 / 6.93 -> 6.22 / 7.53 / 6.78 cm; check / check2, scored once,
/// 8.40 / 6.72 -> 8.12 / 6.69; the 30 bundled clouds 1.95 -> 2.22: two descending flights
/// with both sides unseen read 3.0 / 3.3 -> 6.5 / 8.6 cm off. Measured in the unweighted frame:
/// 0.15 of the steps in from the outermost 6.16 / 10.40 / 6.93, 0.4 in 6.80 / 8.22 / 7.34; the
/// bounded side's quartile with the other side unseen 6.27 / 7.52 / 6.75.) Each side's end is taken
/// where most of the steps put it: with both sides bounded, at its outer quartile over the steps (a
/// shorter end lost part of its tread, a longer one ran onto a surface at tread height beside the
/// flight), or at the outermost where the ends scatter (side_spread_m); with a side unseen, at the
/// outermost on each side (every end reads at most its true one there). Across = the edges' mean
/// direction weighted by their points: the steps' ends agree along the flight in a frame that is
/// not tilted by the fits of short edges (bundled `descending_2`: the unweighted mean put the ends
/// of two steps 2 m apart 9.5 cm apart; bundled width MAE 2.39 -> 2.22 cm, dev sets within 0.02
/// cm).
double widthAcrossSides(const std::vector<TreadScan>& scans, const Staircase& stairs,
                        const StepExtentParams& p) {
    double c2 = 0.0, s2 = 0.0;
    for (const TreadScan& t : scans) {
        const double w = std::max(1, stairs.steps[t.step].num_points);
        const double a = 2.0 * std::atan2(t.edge_u.y(), t.edge_u.x());
        c2 += w * std::cos(a);
        s2 += w * std::sin(a);
    }
    const double alpha = 0.5 * std::atan2(s2, c2);
    const Eigen::Vector2d across(std::cos(alpha), std::sin(alpha));
    std::vector<double> lo, hi;
    for (const TreadScan& t : scans) {
        const StairEdge& e = stairs.steps[t.step];
        const double a = across.dot(e.start.head<2>()), b = across.dot(e.end.head<2>());
        lo.push_back(std::min(a, b));
        hi.push_back(std::max(a, b));
    }
    std::sort(lo.begin(), lo.end());
    std::sort(hi.begin(), hi.end());
    const bool unseen =
        stairs.left_side == StairSide::Unseen || stairs.right_side == StairSide::Unseen;
    // A bounded side whose ends scatter (the outer quartile beyond the median by more than
    // side_spread_m): most steps stopped short of it, at gaps the view left in their treads.
    const std::size_t q = unseen ? 0 : lo.size() / 4, m = lo.size() / 2;
    const std::size_t q_lo = lo[m] - lo[q] > p.side_spread_m ? 0 : q;
    const std::size_t q_hi =
        hi[hi.size() - 1 - q] - hi[hi.size() - 1 - m] > p.side_spread_m ? 0 : q;
    return hi[hi.size() - 1 - q_hi] - lo[q_lo];
}

/// [deg] Largest angle between two of the scans' own edge directions (as lines, 0-90 deg).
double edgeSpreadDeg(const std::vector<TreadScan>& scans) {
    double min_cos = 1.0;
    for (std::size_t a = 0; a < scans.size(); ++a)
        for (std::size_t b = a + 1; b < scans.size(); ++b)
            min_cos = std::min(min_cos, std::abs(scans[a].edge_u.dot(scans[b].edge_u)));
    return std::acos(std::clamp(min_cos, 0.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

void measureStepExtents(const PointCloud& cloud, Staircase& stairs, const StepExtentParams& p) {
    const std::size_t n = stairs.steps.size();
    if (n < 2) return;
    // The floor's edge (descending) and the landing's (ascending) border whole floors.
    const bool up = stairs.direction == StairDirection::Ascending;
    const std::size_t first = up ? 0 : 1, last = up ? n - 1 : n;
    std::vector<TreadScan> scans;
    for (std::size_t k = first; k < last; ++k)
        if (stairs.steps[k].length() > 1e-6)  // else no direction to measure along
            scans.push_back(scanOf(stairs, k, p));
    const bool straight = alignStraightFlight(scans, p.common_direction_max_deg * M_PI / 180.0);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e18), hi = -lo;
    for (const TreadScan& t : scans) {
        const double reach = -t.t0;
        for (double a : {-reach, reach})
            for (double b : {std::min(t.s_lo, -t.nosing_band), std::max(t.s_hi, t.nosing_band)}) {
                const Eigen::Vector2d q = t.c + a * t.u + b * t.n;
                lo = lo.cwiseMin(q);
                hi = hi.cwiseMax(q);
            }
    }
    const ScansAlongFlight along(scans, (hi - lo).norm(), p.index_along_flight);
    for (const Eigen::Vector3f& q : cloud) {
        if (!(q.x() >= lo.x() && q.x() <= hi.x() && q.y() >= lo.y() && q.y() <= hi.y())) continue;
        along.forEachReaching(q, [&](std::size_t k) { addPoint(scans[k], q, p); });
    }
    // A nosing seen in dashes is walked across on straight flights only: a spiral's radial
    // nosing line runs on across the column and past the rim (bundled spiral_0: two steps read
    // 1.50 m for 1.28 m).
    const double open_gap =
        edgeSpreadDeg(scans) <= p.dashed_max_turn_deg ? p.max_open_gap_m : p.side_band_m;
    std::vector<Extent> ext;
    SideVotes left, right;
    for (const TreadScan& t : scans) {
        ext.push_back(measure(t, open_gap, p));
        applyExtent(t, ext.back(), p, stairs.steps[t.step]);
        left.add(ext.back().left);
        right.add(ext.back().right);
    }
    stairs.left_side = left.result();
    stairs.right_side = right.result();
    // Rise, run and heading from the treads as seen: edges lengthened across a hole below would
    // move their centres sideways, and a fit's small angle error there shifts the run (dev r0275:
    // run 1.8 -> 4.8 cm off).
    estimateGeometry(stairs);
    if (boundSidesAcrossHoles(scans, ext, p, stairs))
        stairs.location = stairs.steps.front().centre();
    if (scans.size() < 2) return;
    if (straight) {
        stairs.step_width = widthAcrossSides(scans, stairs, p);
        return;
    }
    // A turning flight's sides share no frame: its steps' own widths.
    std::vector<double> widths;
    for (const TreadScan& t : scans) widths.push_back(stairs.steps[t.step].length());
    stairs.step_width = flightWidth(widths, stairs);
}

}  // namespace stairmap
