#include "core/FlightJoin.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

/// Does `far` (two edges or more) start on `near`'s last level (the same nosing, seen by a second
/// line: within half a run along the heading and the height tolerance)?
bool startsOnLastLevel(const Staircase& near, const Staircase& far, const FlightJoinParams& p) {
    if (far.steps.size() < 2) return false;
    const Eigen::Vector2d h(std::cos(near.heading_rad), std::sin(near.heading_rad));
    const Eigen::Vector3d d = far.steps.front().centre() - near.steps.back().centre();
    return std::abs(h.dot(d.head<2>())) <= 0.5 * near.step_depth &&
           std::abs(d.z()) <= p.height_tolerance_m;
}

/// True when `far` starts beyond `near`'s last edge (or on its level) as a continuation of the
/// same flight: next to it (within max_gap_runs, over the same width) or, `after_unseen`, a few
/// unseen steps further (within max_unseen_steps + 1.5 runs, side by side allowed).
bool continues(const Staircase& near, const Staircase& far, const FlightJoinParams& p,
               bool after_unseen) {
    if (near.direction != far.direction || near.steps.empty() || far.steps.empty()) return false;
    const double max_runs = after_unseen ? p.max_unseen_steps + 1.5 : p.max_gap_runs;
    const bool short_far = far.steps.size() <= 3;
    const double max_turn_deg =
        after_unseen && short_far ? p.short_chain_max_heading_diff_deg : p.max_heading_diff_deg;
    const double turn = std::abs(std::remainder(far.heading_rad - near.heading_rad, 2 * M_PI));
    if (turn > max_turn_deg * M_PI / 180.0) return false;
    const Eigen::Vector2d h(std::cos(near.heading_rad), std::sin(near.heading_rad));
    const StairEdge& last = near.steps.back();
    const StairEdge& first = far.steps.front();
    const double gap = h.dot((first.centre() - last.centre()).head<2>());
    // A chain starting on near's last level is never a piece after unseen steps (those lie a run
    // or more beyond it), so only the adjacent case looks for one.
    const bool shared = !after_unseen && startsOnLastLevel(near, far, p);
    if (!shared && (gap <= 0.0 || gap > max_runs * near.step_depth)) return false;
    const double up = near.direction == StairDirection::Ascending ? 1.0 : -1.0;
    const double climb = up * (first.centre().z() - last.centre().z());
    if (climb < -p.height_tolerance_m || climb > max_runs * near.step_height + p.height_tolerance_m)
        return false;
    // Over the same width: the flights' whole lateral extents, as a facing edge may be a piece.
    const Eigen::Vector2d lateral(-h.y(), h.x());
    const auto a = lateralExtent(near, lateral), b = lateralExtent(far, lateral);
    const double common = std::min(a.second, b.second) - std::max(a.first, b.first);
    if (after_unseen) return common >= -p.max_lateral_gap_m;
    return common >= p.min_lateral_overlap * std::min(a.second - a.first, b.second - b.first);
}

/// True when far's edges are near's steps `first` (1: the next), `first` + 1, ...: one run apart
/// each and on its nosing line.
bool onNosingLine(const Staircase& near, const Staircase& far, const FlightJoinParams& p,
                  int first) {
    const Eigen::Vector2d h(std::cos(near.heading_rad), std::sin(near.heading_rad));
    const double up = near.direction == StairDirection::Ascending ? 1.0 : -1.0;
    const Eigen::Vector3d base = near.steps.back().centre();
    for (std::size_t k = 0; k < far.steps.size(); ++k) {
        const Eigen::Vector3d c = far.steps[k].centre();
        const double n = static_cast<double>(k) + first;  // steps beyond near's last edge
        if (std::abs(h.dot((c - base).head<2>()) - n * near.step_depth) > 0.5 * near.step_depth)
            return false;
        if (std::abs(up * (c.z() - base.z()) - n * near.step_height) > p.height_tolerance_m)
            return false;
    }
    return true;
}

/// Do near's edges (steps 0..n-1) and far's (steps n - 1 + first, ...) lie on one nosing line
/// fitted over both: every edge within the height tolerance of one rise (as onOneRiseAndRun) and
/// within a quarter run of one run (the index pinned)? The fit absorbs part of an offset between
/// the two: a far chain half a 0.17 m rise off its place fits within 3.6 cm. near's own rise may
/// read off by a few mm over its steps, enough to put a far chain five steps on off its line (dev6
/// r0478: 0.141 m read on 0.132 m rises, 4.5 cm off at the far chain's top edge).
bool onCommonNosingLine(const Staircase& near, const Staircase& far, const FlightJoinParams& p,
                        int first) {
    const Eigen::Vector2d h(std::cos(near.heading_rad), std::sin(near.heading_rad));
    std::vector<double> index, z, along;
    const auto add = [&](const StairEdge& e, double k) {
        index.push_back(k);
        z.push_back(e.centre().z());
        along.push_back(h.dot(e.centre().head<2>()));
    };
    const double last = static_cast<double>(near.steps.size()) - 1.0;
    for (std::size_t k = 0; k < near.steps.size(); ++k) add(near.steps[k], static_cast<double>(k));
    for (std::size_t k = 0; k < far.steps.size(); ++k)
        add(far.steps[k], last + first + static_cast<double>(k));
    double rise = 0.0, run = 0.0;
    const double z_worst = lineFitError(index, z, &rise);
    const double along_worst = lineFitError(index, along, &run);
    const double up = near.direction == StairDirection::Ascending ? 1.0 : -1.0;
    return up * rise > 0.0 && run > 0.0 && z_worst <= p.height_tolerance_m &&
           along_worst <= 0.25 * run;
}

/// 0, 1, ..., n - 1: the indices of n edges.
std::vector<double> indices(std::size_t n) {
    std::vector<double> k(n);
    for (std::size_t i = 0; i < n; ++i) k[i] = static_cast<double>(i);
    return k;
}

/// Is `s` one flight: every nosing on one rise (within the height tolerance) and on one run
/// along the heading (within half a run)?
bool onOneRiseAndRun(const Staircase& s, const FlightJoinParams& p) {
    if (s.steps.size() < 3) return true;
    const Eigen::Vector2d h(std::cos(s.heading_rad), std::sin(s.heading_rad));
    std::vector<double> z, along;
    for (const StairEdge& e : s.steps) {
        z.push_back(e.centre().z());
        along.push_back(h.dot(e.centre().head<2>()));
    }
    const std::vector<double> k = indices(z.size());
    double run = 0.0;
    const double z_worst = lineFitError(k, z);
    const double along_worst = lineFitError(k, along, &run);
    return z_worst <= p.height_tolerance_m && along_worst <= 0.5 * std::abs(run);
}

/// `far` starts on `near`'s last level: one flight read as two chains that meet there (a line
/// broken by debris ends one chain, the search starts another at the same nosing). Joined, the
/// level keeping the longer chain's edge, when the whole lies on one rise and run; otherwise the
/// longer chain alone is kept (the shorter one's rise disagrees: a corrupted view).
void joinAtSharedLevel(Staircase& near, const Staircase& far, const FlightJoinParams& p) {
    Staircase joined = near;
    if (far.steps.size() > near.steps.size()) joined.steps.back() = far.steps.front();
    joined.steps.insert(joined.steps.end(), far.steps.begin() + 1, far.steps.end());
    estimateGeometry(joined);
    if (onOneRiseAndRun(joined, p)) near = std::move(joined);
    else if (far.steps.size() > near.steps.size()) near = far;
}

/// How many steps went unseen between `near` and `far` when far continues near's nosing line after
/// them (0 to p.max_unseen_steps); -1 when it does not.
int unseenStepsBetween(const Staircase& near, const Staircase& far, const FlightJoinParams& p) {
    if (!continues(near, far, p, true)) return -1;
    for (int unseen = 0; unseen <= p.max_unseen_steps; ++unseen)
        if (onNosingLine(near, far, p, unseen + 1) || onCommonNosingLine(near, far, p, unseen + 1))
            return unseen;
    return -1;
}

/// Appends far's edges to near's, the `unseen` steps between them put back as near's last edge
/// moved along the line between the two chains' facing edges' centres (num_points 0: unseen).
void appendAfterUnseen(Staircase& near, const Staircase& far, int unseen) {
    const StairEdge last = near.steps.back();
    const Eigen::Vector3d span = far.steps.front().centre() - last.centre();
    for (int n = 1; n <= unseen; ++n) {
        StairEdge e = last;
        const Eigen::Vector3d shift = span * (static_cast<double>(n) / (unseen + 1));
        e.start += shift;
        e.end += shift;
        e.num_points = 0;
        near.steps.push_back(e);
    }
    near.steps.insert(near.steps.end(), far.steps.begin(), far.steps.end());
    estimateGeometry(near);
}

}  // namespace

int joinContinuedFlights(std::vector<Staircase>& found, const FlightJoinParams& params) {
    int removed = 0;
    for (std::size_t i = 0; i < found.size(); ++i) {
        for (std::size_t j = 0; j < found.size(); ++j) {
            if (i == j) continue;
            const int unseen = unseenStepsBetween(found[i], found[j], params);
            if (unseen >= 0)
                appendAfterUnseen(found[i], found[j], unseen);
            else if (!continues(found[i], found[j], params, false))
                continue;
            else if (startsOnLastLevel(found[i], found[j], params))
                joinAtSharedLevel(found[i], found[j], params);
            // otherwise far is a corrupted view of near's far part: dropped
            found.erase(found.begin() + static_cast<std::ptrdiff_t>(j));
            ++removed;
            return removed + joinContinuedFlights(found, params);  // indices moved: start over
        }
    }
    return removed;
}

}  // namespace stairmap
