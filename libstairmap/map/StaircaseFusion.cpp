#include "map/StaircaseFusion.h"

#include <algorithm>
#include <cmath>

#include "map/EdgeFusion.h"
#include "map/StaircaseAssociation.h"
#include "map/StaircaseCanonical.h"

namespace stairmap {
namespace {

constexpr double kDefaultRise = 0.15;  // [m] when a has a single step and no rise estimate

/// Median height offset z_a - z_b over step pairs that are the same stair (pose drift in z).
double heightShift(const Staircase& a, const Staircase& b, const LandmarkParams& params) {
    std::vector<double> dz;
    for (const StairEdge& ea : a.steps) {
        for (const StairEdge& eb : b.steps) {
            if (sameStair(ea, eb, params)) dz.push_back(ea.centre().z() - eb.centre().z());
        }
    }
    if (dz.empty()) return 0.0;
    std::nth_element(dz.begin(), dz.begin() + static_cast<long>(dz.size() / 2), dz.end());
    return dz[dz.size() / 2];
}

/// Keeps the steps ordered bottom to top and fuses neighbours that are the same stair
/// (Definition 2), so that a doubtful pairing can never leave a doubled step behind.
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
                                 const LandmarkParams& params) {
    const double shift = heightShift(a.stairs, b.stairs, params);
    const double half_rise = 0.5 * (a.stairs.step_height > 0.0 ? a.stairs.step_height : kDefaultRise);
    WeightedStaircase out = a;
    std::vector<bool> paired(a.stairs.steps.size(), false);
    for (std::size_t j = 0; j < b.stairs.steps.size(); ++j) {
        const StairEdge& eb = b.stairs.steps[j];
        const double z = eb.centre().z() + shift;
        int best = -1;
        double best_dz = half_rise;
        for (std::size_t i = 0; i < a.stairs.steps.size(); ++i) {
            const double dz = std::abs(a.stairs.steps[i].centre().z() - z);
            if (!paired[i] && dz < best_dz) {
                best = static_cast<int>(i);
                best_dz = dz;
            }
        }
        if (best < 0) {
            out.stairs.steps.push_back(eb);
            out.step_observations.push_back(b.step_observations[j]);
            continue;
        }
        paired[best] = true;
        out.stairs.steps[best] = fuseEdges(a.stairs.steps[best], a.step_observations[best], eb,
                                           b.step_observations[j], a.stairs.heading_rad, params);
        out.step_observations[best] += b.step_observations[j];
    }
    sortAndCollapse(out, params);
    updateCanonicalGeometry(out.stairs);
    return out;
}

}  // namespace stairmap
