#include "core/StaircaseMerge.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/StaircaseCanonical.h"
#include "core/StaircaseGeometry.h"

namespace stairmap {
namespace {

/// Index of a's unpaired step nearest in height to z, within half a rise; -1 if none.
int nearestLevel(const Staircase& a, const std::vector<bool>& paired, double z, double half_rise) {
    int best = -1;
    double best_dz = half_rise;
    for (std::size_t i = 0; i < a.steps.size(); ++i) {
        const double dz = std::abs(a.steps[i].centre().z() - z);
        if (!paired[i] && dz < best_dz) {
            best = static_cast<int>(i);
            best_dz = dz;
        }
    }
    return best;
}

/// Keeps the steps ordered outward (bottom to top when ascending, top to bottom when descending)
/// and fuses neighbours that are the same stair, so a doubtful pairing never leaves a doubled step.
WeightedStaircase orderAndCollapse(const WeightedStaircase& w, const MergeParams& p) {
    const bool up = w.stairs.direction == StairDirection::Ascending;
    std::vector<std::size_t> order(w.stairs.steps.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
        const double zi = w.stairs.steps[i].centre().z(), zj = w.stairs.steps[j].centre().z();
        return up ? zi < zj : zi > zj;
    });
    WeightedStaircase out{w.stairs, {}};
    out.stairs.steps.clear();
    for (const std::size_t i : order) {
        const StairEdge& e = w.stairs.steps[i];
        const int obs = w.step_observations[i];
        if (!out.stairs.steps.empty() && isSameStairEdge(out.stairs.steps.back(), e, p)) {
            out.stairs.steps.back() = fuseEdges(out.stairs.steps.back(), out.step_observations.back(),
                                                e, obs, w.stairs.heading_rad, p);
            out.step_observations.back() += obs;
        } else {
            out.stairs.steps.push_back(e);
            out.step_observations.push_back(obs);
        }
    }
    return out;
}

/// Algorithm 2, line 10, by level: each step of b is fused with a's nearest unpaired step within
/// half a rise, or added. Geometry is left to the caller.
std::optional<WeightedStaircase> pairAndFuse(const WeightedStaircase& a, const WeightedStaircase& b,
                                             const MergeParams& p, StepAnchor anchor) {
    if (a.stairs.direction != b.stairs.direction)
        throw std::invalid_argument("mergeStaircases: directions differ; canonicalise both first");
    if (anchor == StepAnchor::Required && !haveCommonStair(a.stairs, b.stairs, p))
        return std::nullopt;  // NO_MATCH
    const double rise = a.stairs.step_height > 0.0 ? a.stairs.step_height : p.default_rise_m;
    WeightedStaircase out = a;
    std::vector<bool> paired(a.stairs.steps.size(), false);
    for (std::size_t j = 0; j < b.stairs.steps.size(); ++j) {
        const StairEdge& eb = b.stairs.steps[j];
        const int i = nearestLevel(a.stairs, paired, eb.centre().z(), 0.5 * rise);
        if (i < 0) {
            out.stairs.steps.push_back(eb);
            out.step_observations.push_back(b.step_observations[j]);
            continue;
        }
        paired[i] = true;
        out.stairs.steps[i] = fuseEdges(a.stairs.steps[i], a.step_observations[i], eb,
                                        b.step_observations[j], a.stairs.heading_rad, p);
        out.step_observations[i] += b.step_observations[j];
    }
    // A side seen bounded (wall / open) by either detection stays bounded; a conflict keeps a's.
    if (out.stairs.left_side == StairSide::Unseen) out.stairs.left_side = b.stairs.left_side;
    if (out.stairs.right_side == StairSide::Unseen) out.stairs.right_side = b.stairs.right_side;
    return orderAndCollapse(out, p);
}

void requireWeights(const WeightedStaircase& w) {
    if (w.stairs.direction != StairDirection::Ascending)
        throw std::invalid_argument("mergeCanonical: input is not canonical (Ascending)");
    if (w.step_observations.size() != w.stairs.steps.size())
        throw std::invalid_argument("mergeCanonical: step_observations size differs from steps");
}

}  // namespace

bool haveCommonStair(const Staircase& a, const Staircase& b, const MergeParams& params) {
    for (const StairEdge& ea : a.steps) {
        for (const StairEdge& eb : b.steps) {
            if (isSameStairEdge(ea, eb, params)) return true;
        }
    }
    return false;
}

std::optional<Staircase> mergeStaircases(const Staircase& a, const Staircase& b,
                                         const MergeParams& params) {
    params.validate();
    const WeightedStaircase wa{a, std::vector<int>(a.steps.size(), 1)};
    const WeightedStaircase wb{b, std::vector<int>(b.steps.size(), 1)};
    std::optional<WeightedStaircase> merged = pairAndFuse(wa, wb, params, StepAnchor::Required);
    if (!merged) return std::nullopt;
    estimateGeometry(merged->stairs);  // Algorithm 2, line 11
    return std::move(merged->stairs);
}

std::optional<WeightedStaircase> mergeCanonical(const WeightedStaircase& a,
                                                const WeightedStaircase& b,
                                                const MergeParams& params, StepAnchor anchor) {
    params.validate();
    requireWeights(a);
    requireWeights(b);
    std::optional<WeightedStaircase> merged = pairAndFuse(a, b, params, anchor);
    if (merged) updateCanonicalGeometry(merged->stairs);  // Algorithm 2, line 11
    return merged;
}

}  // namespace stairmap
