#pragma once
// The upper median of a few values (the middle one; of an even count, the larger of the two middle
// ones): robust references inside the detector and the export, where a value that occurs must be
// returned rather than an average of two.

#include <algorithm>
#include <vector>

namespace stairmap {

/// The element at position size/2 of `v` sorted; `v` must not be empty. O(n), `v` is a copy.
inline double upperMedian(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

}  // namespace stairmap
