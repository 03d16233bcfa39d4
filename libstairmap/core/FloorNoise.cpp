#include "core/FloorNoise.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stairmap {

double floorHeightNoise(const PointCloud& cloud, double floor_z, const FloorNoiseParams& p) {
    const double r2_lo = p.inner_radius_m * p.inner_radius_m;
    const double r2_hi = p.outer_radius_m * p.outer_radius_m;
    const std::size_t budget = static_cast<std::size_t>(std::max(p.max_points_visited, 1));
    const std::size_t stride = (cloud.size() + budget - 1) / budget;
    std::vector<double> heights;
    for (std::size_t i = 0; i < cloud.size(); i += stride) {
        const Eigen::Vector3f& q = cloud[i];
        const double r2 = static_cast<double>(q.x()) * q.x() + static_cast<double>(q.y()) * q.y();
        // NaN fails every comparison and is skipped.
        if (r2 >= r2_lo && r2 <= r2_hi && std::abs(q.z() - floor_z) <= p.band_m)
            heights.push_back(q.z());
    }
    if (heights.empty() || static_cast<int>(heights.size()) < p.min_points) return 0.0;
    const auto mid = heights.begin() + static_cast<std::ptrdiff_t>(heights.size() / 2);
    std::nth_element(heights.begin(), mid, heights.end());
    const double median = *mid;
    double deviation = 0.0;
    for (double z : heights) deviation += std::abs(z - median);
    constexpr double kGaussianSigmaPerMeanDeviation = 1.2533;  // sqrt(pi / 2)
    return kGaussianSigmaPerMeanDeviation * deviation / static_cast<double>(heights.size());
}

}  // namespace stairmap
