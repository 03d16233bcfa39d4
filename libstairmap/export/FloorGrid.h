#pragma once
// A 2D map of one floor, rasterised from the voxel map's occupied voxel centres (world frame).
// Cell (ix, iy) covers [origin_x + ix * res, origin_x + (ix + 1) * res) and likewise in y, so row
// 0 is the lowest y (the lower-left corner is the origin, as in ROS map_server's `origin`).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap::exporting {

enum class Cell : std::uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

struct FloorGrid {
    double floor_z = 0.0;        ///< [m] world height of the walking surface
    double origin_x = 0.0;       ///< [m] world x of the lower-left corner of cell (0, 0)
    double origin_y = 0.0;       ///< [m] world y of that corner
    double resolution_m = 0.05;  ///< [m] cell edge
    int width = 0, height = 0;   ///< cells along x and y
    std::vector<Cell> cells;     ///< row-major, row 0 = lowest y

    Cell at(int ix, int iy) const { return cells[static_cast<std::size_t>(iy) * width + ix]; }
    Cell& at(int ix, int iy) { return cells[static_cast<std::size_t>(iy) * width + ix]; }
    bool contains(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width && iy < height; }
    /// The cell holding world (x, y), if inside the grid.
    std::optional<std::pair<int, int>> cellOf(double x, double y) const;
    Eigen::Vector2d cellCentre(int ix, int iy) const {
        return {origin_x + (ix + 0.5) * resolution_m, origin_y + (iy + 0.5) * resolution_m};
    }
};

struct FloorRasterParams {
    double resolution_m = 0.05;  ///< [m] cell edge (the export uses the voxel map's resolution)
    double floor_band_m = 0.1;   ///< [m] voxel centres within +- this of the floor are its surface
    /// [m] obstacles start this high above the floor (lower voxels are floor roughness and noise;
    /// keep it below the lowest riser so that a flight's first steps block the floor map)
    double obstacle_min_height_m = 0.1;
    double robot_height_m = 0.7;  ///< [m] voxels up to this height above the floor are obstacles
    double margin_m = 0.5;        ///< [m] unknown border around what was seen
};

/// Free where the floor surface was seen, Occupied where a voxel lies between
/// floor + obstacle_min_height and floor + robot_height (wins over Free), Unknown elsewhere.
/// The grid spans the xy extent of the voxels in that height band plus the margin; with no such
/// voxel it is empty (width = height = 0). Throws std::invalid_argument for a non-positive
/// resolution. Cost: O(voxels + cells).
FloorGrid rasteriseFloor(const PointCloud& voxel_centres_world, double floor_z,
                         const FloorRasterParams& params);

/// Extent of the Free cells [m]: min x, min y, max x, max y; nullopt without any.
std::optional<Eigen::Vector4d> freeExtent(const FloorGrid& grid);

}  // namespace stairmap::exporting
