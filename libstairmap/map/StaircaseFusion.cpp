#include "map/StaircaseFusion.h"

#include <algorithm>

#include "map/EdgeFusion.h"
#include "map/StaircaseAssociation.h"
#include "map/StaircaseCanonical.h"

namespace stairmap {
namespace {

/// Keeps the steps ordered bottom to top and fuses neighbours that are the same stair
/// (Definition 2), so that a misaligned fusion can never leave a doubled step behind.
void sortAndCollapse(WeightedStaircase& w, const LandmarkParams& params) {
    std::vector<std::size_t> order(w.stairs.steps.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return w.stairs.steps[a].centre().z() < w.stairs.steps[b].centre().z();
    });
    WeightedStaircase out;
    out.stairs = w.stairs;
    out.stairs.steps.clear();
    for (const std::size_t i : order) {
        const StairEdge& e = w.stairs.steps[i];
        const int obs = w.step_observations[i];
        if (!out.stairs.steps.empty() && sameStair(out.stairs.steps.back(), e, params)) {
            out.stairs.steps.back() = fuseEdges(out.stairs.steps.back(),
                                                out.step_observations.back(), e, obs,
                                                w.stairs.heading_rad, params);
            out.step_observations.back() += obs;
        } else {
            out.stairs.steps.push_back(e);
            out.step_observations.push_back(obs);
        }
    }
    w = std::move(out);
}

}  // namespace

WeightedStaircase fuseStaircases(const WeightedStaircase& a, const WeightedStaircase& b,
                                 int offset, const LandmarkParams& params) {
    const int na = static_cast<int>(a.stairs.steps.size());
    const int nb = static_cast<int>(b.stairs.steps.size());
    // Never leave a gap of unseen steps between the two flights.
    offset = std::clamp(offset, -nb, na);
    const double uphill = a.stairs.heading_rad;
    WeightedStaircase out;
    out.stairs = a.stairs;
    out.stairs.steps.clear();
    for (int idx = std::min(0, offset); idx < std::max(na, offset + nb); ++idx) {
        const int ib = idx - offset;
        const bool in_a = idx >= 0 && idx < na;
        const bool in_b = ib >= 0 && ib < nb;
        if (in_a && in_b) {
            const int wa = a.step_observations[idx], wb = b.step_observations[ib];
            out.stairs.steps.push_back(
                fuseEdges(a.stairs.steps[idx], wa, b.stairs.steps[ib], wb, uphill, params));
            out.step_observations.push_back(wa + wb);
        } else if (in_a) {
            out.stairs.steps.push_back(a.stairs.steps[idx]);
            out.step_observations.push_back(a.step_observations[idx]);
        } else if (in_b) {
            out.stairs.steps.push_back(b.stairs.steps[ib]);
            out.step_observations.push_back(b.step_observations[ib]);
        }
    }
    sortAndCollapse(out, params);
    updateCanonicalGeometry(out.stairs);
    return out;
}

}  // namespace stairmap
