#include "core/ReverseReadings.h"

#include <algorithm>

#include "core/MergeParams.h"
#include "core/StairEdgeFusion.h"

namespace stairmap {
namespace {

/// How many of `a`'s edges are the same stair edge as one of `b`'s.
int sharedEdges(const Staircase& a, const Staircase& b) {
    const MergeParams m;
    int shared = 0;
    for (const StairEdge& e : a.steps)
        shared += std::any_of(b.steps.begin(), b.steps.end(),
                              [&](const StairEdge& f) { return isSameStairEdge(e, f, m); });
    return shared;
}

/// Are ascending `up` and descending `down` one flight read both ways?
bool readBothWays(const Staircase& up, const Staircase& down, const ReverseReadingParams& p) {
    const Staircase& shorter = up.steps.size() < down.steps.size() ? up : down;
    const Staircase& longer = &shorter == &up ? down : up;
    const int shared = sharedEdges(shorter, longer);
    return shared >= p.min_shared_edges &&
           shared >= p.min_shared_fraction * static_cast<double>(shorter.steps.size());
}

}  // namespace

int dropReverseReadings(std::vector<Staircase>& flights, const ReverseReadingParams& params) {
    std::vector<bool> drop(flights.size(), false);
    for (std::size_t i = 0; i < flights.size(); ++i) {
        if (flights[i].direction != StairDirection::Ascending) continue;
        for (std::size_t j = 0; j < flights.size(); ++j) {
            if (flights[j].direction != StairDirection::Descending || drop[i] || drop[j]) continue;
            if (!readBothWays(flights[i], flights[j], params)) continue;
            // the longer reading stays; on a tie the ascending one
            if (flights[i].steps.size() >= flights[j].steps.size())
                drop[j] = true;
            else
                drop[i] = true;
        }
    }
    int dropped = 0;
    for (std::size_t k = flights.size(); k-- > 0;)
        if (drop[k]) {
            flights.erase(flights.begin() + static_cast<std::ptrdiff_t>(k));
            ++dropped;
        }
    return dropped;
}

}  // namespace stairmap
