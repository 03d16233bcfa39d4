#include "core/FloorEstimation.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stairmap {

std::optional<double> dominantLevel(const PointCloud& cloud, const FloorSearch& s) {
    if (!(s.z_hi > s.z_lo) || !(s.bin_m > 0)) return std::nullopt;
    const int bins = static_cast<int>(std::ceil((s.z_hi - s.z_lo) / s.bin_m)) + 1;
    std::vector<int> hist(bins, 0);
    const float r2 = static_cast<float>(s.radius_m * s.radius_m);
    const float lo = static_cast<float>(s.z_lo), hi = static_cast<float>(s.z_hi);
    const float inv_bin = static_cast<float>(1.0 / s.bin_m);
    // A level is found from ~10k points: large clouds are subsampled. The heights of the sampled
    // points within the radius are read from the cloud once (strided reads miss the cache) and
    // serve both the histogram and the refinement.
    const std::size_t stride = std::max<std::size_t>(1, cloud.size() / 10000);
    thread_local std::vector<float> tl_heights;  // scratch re-used between calls
    std::vector<float>& heights = tl_heights;
    heights.clear();
    for (std::size_t i = 0; i < cloud.size(); i += stride) {
        const auto& p = cloud[i];
        if (p.x() * p.x() + p.y() * p.y() <= r2) heights.push_back(p.z());  // false for NaN
    }
    for (const float z : heights) {
        // Comparisons are false for NaN, so non-finite points drop out here.
        if (!(z >= lo && z <= hi)) continue;
        ++hist[static_cast<int>((z - lo) * inv_bin)];
    }
    int best = -1, best_count = 0;
    for (int b = 0; b < bins; ++b) {
        const int c = hist[b] + (b > 0 ? hist[b - 1] : 0) + (b + 1 < bins ? hist[b + 1] : 0);
        if (c > best_count) {
            best_count = c;
            best = b;
        }
    }
    if (best < 0 || best_count < s.min_support) return std::nullopt;
    const double centre = s.z_lo + (best + 0.5) * s.bin_m;
    double sum = 0.0;
    int count = 0;
    for (const float z : heights) {
        if (!(std::abs(z - centre) <= 1.5 * s.bin_m)) continue;
        sum += z;
        ++count;
    }
    if (count == 0) return centre;
    return sum / count;
}

}  // namespace stairmap
