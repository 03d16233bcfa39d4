#include "core/DescentEnd.h"

#include <algorithm>

namespace stairmap {

bool dropCropLineEnd(std::vector<LineSegment>& edges, const DescentEndParams& params) {
    if (edges.size() < 2) return false;
    double longest_other = 0.0;
    for (std::size_t k = 0; k + 1 < edges.size(); ++k)
        longest_other = std::max(longest_other, edges[k].length());
    if (edges.back().length() <= params.max_length_ratio * longest_other) return false;
    edges.pop_back();
    return true;
}

}  // namespace stairmap
