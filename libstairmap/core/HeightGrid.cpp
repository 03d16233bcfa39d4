#include "core/HeightGrid.h"

#include <algorithm>
#include <cmath>

namespace stairmap {

void HeightGrid::fill(const PointCloud& cloud, const Eigen::Vector2d& centre, double half_size_m,
                      double cell_m, double z_lo, double z_hi) {
    cell = cell_m;
    const int inner = static_cast<int>(std::ceil(2.0 * half_size_m / cell_m));
    n = inner + 2;
    origin = centre - Eigen::Vector2d::Constant((0.5 * inner + 1.0) * cell_m);
    top.assign(static_cast<std::size_t>(n) * n, kEmpty);
    const float inv = static_cast<float>(1.0 / cell_m);
    const float x0 = static_cast<float>(origin.x()), y0 = static_cast<float>(origin.y());
    const float hi = static_cast<float>(n - 1);
    const float zl = static_cast<float>(z_lo), zh = static_cast<float>(z_hi);
    for (const Eigen::Vector3f& q : cloud) {
        const float fx = (q.x() - x0) * inv, fy = (q.y() - y0) * inv;
        // written so that NaN fails every test; the border stays empty
        if (!(q.z() >= zl && q.z() <= zh && fx >= 1 && fy >= 1 && fx < hi && fy < hi)) continue;
        float& t = top[static_cast<std::size_t>(fy) * n + static_cast<std::size_t>(fx)];
        t = std::max(t, q.z());
    }
}

}  // namespace stairmap
