#pragma once
// Hand-made 2.5D clouds as a legged robot's elevation map sees the ground: one point per cell on
// the top surface, no vertical faces, nothing mapped outside the map's extent.

#include <functional>

#include "core/PointCloud.h"

namespace stairmap::test {

/// One point per `cell` over x in [x_min, x_max), y in [-half_width, half_width] at height h(x, y)
/// [m]; cells where h returns NaN are unmapped (no point).
inline PointCloud heightField(const std::function<double(double, double)>& h, double x_min,
                              double x_max, double half_width, double cell) {
    PointCloud cloud;
    for (double x = x_min; x < x_max; x += cell)
        for (double y = -half_width; y <= half_width; y += cell) {
            const double z = h(x, y);
            if (z == z) cloud.emplace_back(float(x), float(y), float(z));
        }
    return cloud;
}

}  // namespace stairmap::test
