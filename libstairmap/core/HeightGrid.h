#pragma once
// A coarse top surface: the highest point of every cell of a square XY grid (the paper's top view,
// Sec. III-A, at a coarser cell and over a smaller area). TreadBoundaries reads treads from it.

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap {

struct HeightGrid {
    static constexpr float kEmpty = -std::numeric_limits<float>::infinity();

    int n = 0;  ///< cells per side, including a border of one empty cell on every side
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< [m] lower corner of cell 0 (border)
    double cell = 0;                                   ///< [m] cell size
    std::vector<float> top;  ///< [m] highest z per cell (row-major, rows along y), kEmpty = none

    /// Clears the grid to cover `centre` +- half_size_m (rounded up to whole cells) with cells of
    /// cell_m, then raises every cell to its highest point of `cloud` within [z_lo, z_hi]
    /// (non-finite points are ignored). Memory: (2 half_size_m / cell_m + 2)^2 floats.
    void fill(const PointCloud& cloud, const Eigen::Vector2d& centre, double half_size_m,
              double cell_m, double z_lo, double z_hi);
    /// [m] XY centre of cell `index`
    Eigen::Vector2d centre(int index) const {
        return origin + Eigen::Vector2d(index % n + 0.5, index / n + 0.5) * cell;
    }
};

}  // namespace stairmap
