#include "export/FloorGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stairmap::exporting {
namespace {

struct Band {
    double floor_lo, floor_hi, obstacle_lo, obstacle_hi;
    bool floor(double z) const { return z >= floor_lo && z <= floor_hi; }
    bool obstacle(double z) const { return z > obstacle_lo && z <= obstacle_hi; }
};

Band bandFor(double floor_z, const FloorRasterParams& p) {
    return {floor_z - p.floor_band_m, floor_z + p.floor_band_m, floor_z + p.obstacle_min_height_m,
            floor_z + p.robot_height_m};
}

/// Sizes the grid to the voxels of the band (plus margin); false if there are none.
bool sizeGrid(const PointCloud& voxels, const Band& band, const FloorRasterParams& p,
              FloorGrid& grid) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(kInf, kInf), hi(-kInf, -kInf);
    for (const Eigen::Vector3f& v : voxels) {
        if (!v.allFinite() || !(band.floor(v.z()) || band.obstacle(v.z()))) continue;
        lo = lo.cwiseMin(v.head<2>().cast<double>());
        hi = hi.cwiseMax(v.head<2>().cast<double>());
    }
    if (!(lo.x() <= hi.x())) return false;
    const double r = p.resolution_m;
    // Snap the origin to the resolution grid so that cells line up with the voxels.
    grid.origin_x = std::floor((lo.x() - p.margin_m) / r) * r;
    grid.origin_y = std::floor((lo.y() - p.margin_m) / r) * r;
    grid.width = static_cast<int>(std::ceil((hi.x() + p.margin_m - grid.origin_x) / r)) + 1;
    grid.height = static_cast<int>(std::ceil((hi.y() + p.margin_m - grid.origin_y) / r)) + 1;
    grid.cells.assign(static_cast<std::size_t>(grid.width) * grid.height, Cell::Unknown);
    return true;
}

}  // namespace

std::optional<std::pair<int, int>> FloorGrid::cellOf(double x, double y) const {
    const int ix = static_cast<int>(std::floor((x - origin_x) / resolution_m));
    const int iy = static_cast<int>(std::floor((y - origin_y) / resolution_m));
    if (!contains(ix, iy)) return std::nullopt;
    return std::make_pair(ix, iy);
}

FloorGrid rasteriseFloor(const PointCloud& voxels, double floor_z, const FloorRasterParams& p) {
    if (!(p.resolution_m > 0.0) || !std::isfinite(p.resolution_m)) {
        throw std::invalid_argument("FloorRasterParams.resolution_m: must be > 0");
    }
    FloorGrid grid;
    grid.floor_z = floor_z;
    grid.resolution_m = p.resolution_m;
    const Band band = bandFor(floor_z, p);
    if (!sizeGrid(voxels, band, p, grid)) return grid;
    for (const Eigen::Vector3f& v : voxels) {
        if (!v.allFinite()) continue;
        const bool obstacle = band.obstacle(v.z());
        if (!obstacle && !band.floor(v.z())) continue;
        const auto cell = grid.cellOf(v.x(), v.y());
        if (!cell) continue;
        Cell& c = grid.at(cell->first, cell->second);
        if (obstacle)
            c = Cell::Occupied;
        else if (c == Cell::Unknown)
            c = Cell::Free;
    }
    return grid;
}

std::optional<Eigen::Vector4d> freeExtent(const FloorGrid& grid) {
    int x0 = grid.width, y0 = grid.height, x1 = -1, y1 = -1;
    for (int iy = 0; iy < grid.height; ++iy) {
        for (int ix = 0; ix < grid.width; ++ix) {
            if (grid.at(ix, iy) != Cell::Free) continue;
            x0 = std::min(x0, ix), y0 = std::min(y0, iy);
            x1 = std::max(x1, ix), y1 = std::max(y1, iy);
        }
    }
    if (x1 < 0) return std::nullopt;
    const double r = grid.resolution_m;
    return Eigen::Vector4d(grid.origin_x + x0 * r, grid.origin_y + y0 * r,
                           grid.origin_x + (x1 + 1) * r, grid.origin_y + (y1 + 1) * r);
}

}  // namespace stairmap::exporting
