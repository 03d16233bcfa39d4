#include "core/ProfileChains.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include "core/MissingNosings.h"

namespace stairmap {

namespace {

/// A line seen across a seed: its distance up the flight, its height and its lateral extent.
struct Across {
    int index = 0;
    double s = 0.0;             ///< [m] along the seed's normal, away from the origin
    double z = 0.0;             ///< [m]
    double lo = 0.0, hi = 0.0;  ///< [m] extent along the seed's direction
};

/// A comb: step k's nosing at s0 + k run, z0 + k rise; its teeth's members (line indices).
struct Comb {
    double s0 = 0.0, z0 = 0.0, run = 0.0, rise = 0.0;
    std::map<int, std::vector<int>> teeth;  ///< tooth index -> positions in the `across` list
    int points = 0;
};

double spacingTolerance(double run, const ProfileChainParams& p) {
    return std::max(0.04, p.spacing_tolerance * run);
}

/// The tooth of the comb (s0, z0, run, rise) that `a` stands on: within `tol` of a whole number
/// of runs up the flight, and from `below` under to `above` over that tooth's height.
std::optional<int> toothOf(const Across& a, double s0, double z0, double run, double rise,
                           double tol, double below, double above) {
    const int k = static_cast<int>(std::lround((a.s - s0) / run));
    if (std::abs(a.s - s0 - k * run) > tol) return std::nullopt;
    const double dz = a.z - (z0 + k * rise);
    if (dz < -below || dz > above) return std::nullopt;
    return k;
}

/// The teeth of the comb (s0, z0, run, rise) that the lines of `across` hold.
Comb collect(const std::vector<Across>& across, const std::vector<LineSegment>& lines, double s0,
             double z0, double run, double rise, double below, double above,
             const ProfileChainParams& p) {
    Comb comb{s0, z0, run, rise, {}, 0};
    const double tol = spacingTolerance(run, p);
    for (std::size_t a = 0; a < across.size(); ++a) {
        const auto k = toothOf(across[a], s0, z0, run, rise, tol, below, above);
        if (!k) continue;
        comb.teeth[*k].push_back(static_cast<int>(a));
        comb.points += lines[across[a].index].num_points;
    }
    return comb;
}

/// The teeth and points `collect` would find, without building the comb (the search scores
/// many hypotheses and keeps one): `ks` is scratch space.
std::pair<int, int> score(const std::vector<Across>& across, const std::vector<LineSegment>& lines,
                          double s0, double z0, double run, double rise, double below,
                          double above, const ProfileChainParams& p, std::vector<int>& ks) {
    ks.clear();
    int points = 0;
    const double tol = spacingTolerance(run, p);
    for (const Across& a : across) {
        const auto k = toothOf(a, s0, z0, run, rise, tol, below, above);
        if (!k) continue;
        ks.push_back(*k);
        points += lines[a.index].num_points;
    }
    std::sort(ks.begin(), ks.end());
    return {static_cast<int>(std::unique(ks.begin(), ks.end()) - ks.begin()), points};
}

/// The tooth member (position in `across`) whose line is the longest.
int longestMember(const std::vector<int>& members, const std::vector<Across>& across,
                  const std::vector<LineSegment>& lines) {
    return *std::max_element(members.begin(), members.end(), [&](int a, int b) {
        return lines[across[a].index].length() < lines[across[b].index].length();
    });
}

/// Least-squares refit of s and z against the tooth index, one (longest) member per tooth.
void refit(Comb& comb, const std::vector<Across>& across, const std::vector<LineSegment>& lines) {
    double n = 0, sk = 0, skk = 0, ss = 0, sks = 0, sz = 0, skz = 0;
    for (const auto& [k, members] : comb.teeth) {
        const int best = longestMember(members, across, lines);
        n += 1;
        sk += k;
        skk += double(k) * k;
        ss += across[best].s;
        sks += k * across[best].s;
        sz += across[best].z;
        skz += k * across[best].z;
    }
    const double det = n * skk - sk * sk;
    if (n < 2 || std::abs(det) < 1e-9) return;
    comb.run = (n * sks - sk * ss) / det;
    comb.s0 = (ss - comb.run * sk) / n;
    comb.rise = (n * skz - sk * sz) / det;
    comb.z0 = (sz - comb.rise * sk) / n;
}

/// The longest run of teeth in which consecutive ones are at most max_gap + 1 apart.
std::vector<int> contiguousTeeth(const Comb& comb, int max_gap) {
    std::vector<int> best, current;
    for (const auto& entry : comb.teeth) {
        const int k = entry.first;
        if (!current.empty() && k - current.back() > max_gap + 1) current.clear();
        current.push_back(k);
        if (current.size() > best.size()) best = current;
    }
    return best;
}

/// The seed's best comb among `across` (seed first): every pair with it proposes a run and a
/// rise (1 .. max_multiple steps apart); the comb holding most teeth wins (then most points).
Comb bestComb(const std::vector<Across>& across, const std::vector<LineSegment>& lines,
              const ProfileChainParams& p) {
    int best_teeth = 0, best_points = 0;
    double best_run = 0.0, best_rise = 0.0;
    std::vector<int> ks;
    const double tol = p.below_tolerance_m;  // the seed may be low or high itself
    const double reach = p.max_multiple * p.max_run_m + spacingTolerance(p.max_run_m, p);
    for (std::size_t j = 1; j < across.size(); ++j) {
        const double ds = across[j].s, dz = across[j].z - across[0].z;
        if (std::abs(ds) > reach || ds * dz <= 0) continue;
        for (int m = 1; m <= p.max_multiple; ++m) {
            const double run = std::abs(ds) / m, rise = std::abs(dz) / m;
            if (run < p.min_run_m || run > p.max_run_m ||
                rise < p.min_rise_m - p.below_tolerance_m ||
                rise > p.max_rise_m + p.below_tolerance_m)
                continue;
            const auto [teeth, points] =
                score(across, lines, 0.0, across[0].z, run, rise, tol, tol, p, ks);
            if (teeth > best_teeth || (teeth == best_teeth && points > best_points)) {
                best_teeth = teeth;
                best_points = points;
                best_run = run;
                best_rise = rise;
            }
        }
    }
    if (best_teeth == 0) return {};
    return collect(across, lines, 0.0, across[0].z, best_run, best_rise, tol, tol, p);
}

/// How many distinct distances up the flight the lines of `across` stand at (closer than a
/// tooth's tolerance at the shortest run counts as one): a comb needs as many as its teeth.
int distinctDistances(const std::vector<Across>& across, const ProfileChainParams& p) {
    std::vector<double> s;
    s.reserve(across.size());
    for (const Across& a : across) s.push_back(a.s);
    std::sort(s.begin(), s.end());
    const double tol = spacingTolerance(p.min_run_m, p);
    int distinct = 0;
    double last = -std::numeric_limits<double>::infinity();
    for (const double v : s)
        if (v - last > tol) {
            ++distinct;
            last = v;
        }
    return distinct;
}

/// The frame lines are seen across: a point on the seed, the nosings' direction and the normal
/// up the flight.
struct Frame {
    Eigen::Vector2d c0 = Eigen::Vector2d::Zero(), u = Eigen::Vector2d::UnitX(),
                    n = Eigen::Vector2d::UnitY();
};

Frame frameOf(const LineSegment& seed, const Eigen::Vector2d& u) {
    Frame f{seed.centre(), u, Eigen::Vector2d(u.y(), -u.x())};
    if (f.n.dot(seed.centre()) < 0) f.n = -f.n;  // up the flight: away from the origin
    return f;
}

/// The teeth's lines' mean direction, each weighted by its length and turned to `u0`'s sense.
Eigen::Vector2d meanDirection(const Comb& comb, const std::vector<Across>& across,
                              const std::vector<LineSegment>& lines, const Eigen::Vector2d& u0) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const auto& entry : comb.teeth)
        for (const int a : entry.second) {
            const LineSegment& l = lines[across[a].index];
            const Eigen::Vector2d d = l.direction();
            sum += (d.dot(u0) < 0 ? -d : d) * l.length();
        }
    return sum.norm() > 0 ? Eigen::Vector2d(sum.normalized()) : u0;
}

/// The seed's lines seen across it: parallel within max_turn_deg and within max_lateral_m.
std::vector<Across> acrossSeed(const std::vector<LineSegment>& lines,
                               const std::vector<Eigen::Vector2d>& directions, std::size_t seed,
                               const Frame& frame, const std::vector<char>& taken,
                               const ProfileChainParams& p) {
    const LineSegment& l0 = lines[seed];
    const Eigen::Vector2d &u = frame.u, &n = frame.n, &c0 = frame.c0;
    const double cos_max = std::cos(p.max_turn_deg * M_PI / 180.0);
    const double lo0 = std::min(u.dot(l0.start - c0), u.dot(l0.end - c0));
    const double hi0 = std::max(u.dot(l0.start - c0), u.dot(l0.end - c0));
    std::vector<Across> out{{static_cast<int>(seed), 0.0, l0.z, lo0, hi0}};
    for (std::size_t j = 0; j < lines.size(); ++j) {
        if (j == seed || taken[j]) continue;
        const LineSegment& l = lines[j];
        if (std::abs(directions[j].dot(u)) < cos_max) continue;
        const double a = u.dot(l.start - c0), b = u.dot(l.end - c0);
        const double lo = std::min(a, b), hi = std::max(a, b);
        if (std::max(hi, hi0) - std::min(lo, lo0) > p.max_lateral_m) continue;
        out.push_back({static_cast<int>(j), n.dot(l.centre() - c0), l.z, lo, hi});
    }
    return out;
}

/// The comb's chain from the floor outward (see findProfileChains), or empty when it fails the
/// bounds, the gaps or the floor's anchor. Every edge lies on the comb: along the nosings'
/// direction, at its tooth's distance up the flight, across its members' lateral extent, at the
/// height of its longest member (its seen points and covariance too).
std::vector<LineSegment> chainOf(const Comb& comb, const std::vector<int>& teeth,
                                 const std::vector<Across>& across,
                                 const std::vector<LineSegment>& lines, const Frame& frame,
                                 const ProfileChainParams& p) {
    if (static_cast<int>(teeth.size()) < p.min_seen_steps) return {};
    if (comb.rise < p.min_rise_m || comb.rise > p.max_rise_m || comb.run < p.min_run_m ||
        comb.run > p.max_run_m)
        return {};
    const double first_z = comb.z0 + teeth.front() * comb.rise;
    const double steps_up = (first_z - p.floor_z) / comb.rise;
    const int first_step = static_cast<int>(std::lround(steps_up));
    if (first_step < 1 || first_step > p.max_first_step ||
        std::abs(steps_up - first_step) > p.floor_tolerance_rises)
        return {};
    const auto edgeAt = [&](double k, double lo, double hi, double z) {
        const Eigen::Vector2d c = frame.c0 + (comb.s0 + k * comb.run) * frame.n;
        return unseenNosing(c + lo * frame.u, c + hi * frame.u, z);
    };
    // One per tooth from the first seen one to the last; a tooth without a line gets its
    // neighbours' extent and height halfway (gaps are single teeth).
    std::vector<LineSegment> seen;
    std::vector<char> is_seen;
    for (int k = teeth.front(); k <= teeth.back(); ++k) {
        const auto it = comb.teeth.find(k);
        if (it == comb.teeth.end()) {
            seen.emplace_back();
            is_seen.push_back(0);
            continue;
        }
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const int a : it->second) {
            lo = std::min(lo, across[a].lo);
            hi = std::max(hi, across[a].hi);
        }
        const int best = longestMember(it->second, across, lines);
        const LineSegment& member = lines[across[best].index];
        LineSegment edge = edgeAt(k, lo, hi, member.z);
        edge.cov = member.cov;
        edge.num_points = member.num_points;
        seen.push_back(edge);
        is_seen.push_back(1);
    }
    for (std::size_t i = 1; i + 1 < seen.size(); ++i)
        if (!is_seen[i]) seen[i] = halfwayNosing(seen[i - 1], seen[i + 1]);
    // The steps below the first seen one, down to the floor: one run and one rise apart.
    const LineSegment& first = seen.front();
    const Eigen::Vector2d down = -frame.n * comb.run;
    std::vector<LineSegment> chain;
    for (int j = 1; j < first_step; ++j) {
        const double back = first_step - j;
        chain.push_back(unseenNosing(first.start + back * down, first.end + back * down,
                                     first.z - back * comb.rise));
    }
    chain.insert(chain.end(), seen.begin(), seen.end());
    return chain;
}

}  // namespace

std::vector<std::vector<LineSegment>> findProfileChains(const std::vector<LineSegment>& lines,
                                                        const ProfileChainParams& p) {
    std::vector<std::size_t> seeds;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].length() >= p.min_seed_length_m && lines[i].z > p.floor_z + 0.5 * p.min_rise_m)
            seeds.push_back(i);
    std::sort(seeds.begin(), seeds.end(),
              [&](std::size_t a, std::size_t b) { return lines[a].length() > lines[b].length(); });
    std::vector<char> taken(lines.size(), 0);
    std::vector<Eigen::Vector2d> directions;  // each line's, once (a sine and a cosine)
    directions.reserve(lines.size());
    for (const LineSegment& l : lines) directions.push_back(l.direction());
    std::vector<std::vector<LineSegment>> chains;
    for (const std::size_t seed : seeds) {
        if (taken[seed]) continue;
        std::vector<Across> across =
            acrossSeed(lines, directions, seed, frameOf(lines[seed], directions[seed]), taken, p);
        if (distinctDistances(across, p) < p.min_seen_steps) continue;
        Comb comb = bestComb(across, lines, p);
        if (static_cast<int>(comb.teeth.size()) < p.min_seen_steps) continue;
        // The seed's own direction may be a few degrees off: over a flight's width that moves a
        // piece's distance up it by centimetres. The teeth's lines, weighted by their lengths,
        // give the nosings' direction; the lines are seen across that once more.
        const Frame frame =
            frameOf(lines[seed], meanDirection(comb, across, lines, directions[seed]));
        across = acrossSeed(lines, directions, seed, frame, taken, p);
        comb = bestComb(across, lines, p);
        if (static_cast<int>(comb.teeth.size()) < p.min_seen_steps) continue;
        refit(comb, across, lines);
        if (!std::isfinite(comb.rise) || !(comb.run >= p.min_run_m && comb.run <= p.max_run_m))
            continue;  // the refit left the bounds (chainOf would refuse it): no comb to collect
        comb = collect(across, lines, comb.s0, comb.z0, comb.run, comb.rise, p.below_tolerance_m,
                       p.above_tolerance_m, p);
        const std::vector<int> teeth = contiguousTeeth(comb, p.max_gap_steps);
        std::vector<LineSegment> chain = chainOf(comb, teeth, across, lines, frame, p);
        if (chain.empty()) continue;
        for (const int k : teeth)
            for (const int a : comb.teeth.at(k)) taken[across[a].index] = 1;
        chains.push_back(std::move(chain));
    }
    return chains;
}

}  // namespace stairmap
