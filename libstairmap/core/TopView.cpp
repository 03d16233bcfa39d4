#include "core/TopView.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stairmap {
namespace {

struct GridBox {
    float x0 = 0, y0 = 0;  // lower corner
    int nx = 0, ny = 0;
    float inv_leaf = 0;
};

bool usable(const Eigen::Vector3f& p, float r2max, float z_lo, float z_hi) {
    return p.z() >= z_lo && p.z() <= z_hi && p.x() * p.x() + p.y() * p.y() <= r2max;
}

/// Pass 1: bounding box of the usable points, padded by `pad` empty columns on every side so
/// that radial neighbour look-ups never leave the grid.
GridBox boundingGrid(const PointCloud& cloud, const TopViewParams& p, int pad) {
    const float r2 = static_cast<float>(p.max_range_m * p.max_range_m);
    const float lo = static_cast<float>(p.z_lo), hi = static_cast<float>(p.z_hi);
    float minx = std::numeric_limits<float>::max(), miny = minx;
    float maxx = -minx, maxy = -minx;
    for (const auto& q : cloud) {
        if (!usable(q, r2, lo, hi)) continue;
        minx = std::min(minx, q.x());
        maxx = std::max(maxx, q.x());
        miny = std::min(miny, q.y());
        maxy = std::max(maxy, q.y());
    }
    GridBox box;
    if (minx > maxx) return box;
    box.inv_leaf = static_cast<float>(1.0 / p.leaf_m);
    // Grid aligned to multiples of the leaf so cells do not depend on the cloud's extent.
    box.x0 = (std::floor(minx * box.inv_leaf) - pad) / box.inv_leaf;
    box.y0 = (std::floor(miny * box.inv_leaf) - pad) / box.inv_leaf;
    box.nx = static_cast<int>((maxx - box.x0) * box.inv_leaf) + 1 + pad;
    box.ny = static_cast<int>((maxy - box.y0) * box.inv_leaf) + 1 + pad;
    return box;
}

/// Highest point of one XY column; z = -inf for an empty column.
struct ColumnTop {
    float z, x, y;
};

/// Pass 2: the highest point of every column. Storing its x, y next to z keeps the later sweep over
/// the grid sequential (no gather from the cloud).
void highestPoints(const PointCloud& cloud, const TopViewParams& p, const GridBox& box,
                   ColumnTop* grid) {
    const float r2 = static_cast<float>(p.max_range_m * p.max_range_m);
    const float lo = static_cast<float>(p.z_lo), hi = static_cast<float>(p.z_hi);
    for (const auto& q : cloud) {
        if (!usable(q, r2, lo, hi)) continue;
        const int ix = static_cast<int>((q.x() - box.x0) * box.inv_leaf);
        const int iy = static_cast<int>((q.y() - box.y0) * box.inv_leaf);
        ColumnTop& c = grid[std::min(iy, box.ny - 1) * box.nx + std::min(ix, box.nx - 1)];
        if (q.z() > c.z) c = {q.z(), q.x(), q.y()};
    }
}

/// Grid offset (8-neighbourhood) of the radial direction away from the robot at (x, y).
int radialOffset(float x, float y, int nx) {
    constexpr float kTan22_5 = 0.41421356f;
    const int ox = std::abs(x) > kTan22_5 * std::abs(y) ? (x > 0 ? 1 : -1) : 0;
    const int oy = std::abs(y) > kTan22_5 * std::abs(x) ? (y > 0 ? 1 : -1) : 0;
    return oy * nx + ox;
}

constexpr int kPad = 3;  ///< empty columns skipped (and grid padding) for the neighbour look-up

/// Height of the first occupied column up to kPad cells along `offset` (empty columns of a sparse
/// cloud are skipped); -inf when all are empty, which then counts as a drop.
inline float neighbourZ(const ColumnTop* grid, int col, int offset) {
    float z = grid[col + offset].z;
    if (z == -std::numeric_limits<float>::infinity()) z = grid[col + 2 * offset].z;
    if (z == -std::numeric_limits<float>::infinity()) z = grid[col + 3 * offset].z;
    return z;
}

}  // namespace

void buildTopView(const PointCloud& cloud, const TopViewParams& p, std::vector<TopViewCell>& cells) {
    cells.clear();
    const GridBox box = boundingGrid(cloud, p, kPad);
    if (box.nx == 0) return;
    const std::size_t ncols = static_cast<std::size_t>(box.nx) * box.ny;
    // Per-thread scratch grid: re-used between calls, so no page faults for fresh memory.
    thread_local std::vector<ColumnTop> tl_grid;
    std::vector<ColumnTop>& grid_store = tl_grid;
    grid_store.assign(ncols, {-std::numeric_limits<float>::infinity(), 0.f, 0.f});
    const ColumnTop* grid = grid_store.data();
    highestPoints(cloud, p, box, grid_store.data());
    const float min_dz = static_cast<float>(p.edge_min_dz_m);
    const float spill_dz = static_cast<float>(p.edge_spill_dz_m);
    for (int iy = 0; iy < box.ny; ++iy) {
        // Direction from the robot, taken at the column centre (grid-aligned, no point noise).
        const float cy = box.y0 + (iy + 0.5f) / box.inv_leaf;
        for (int ix = 0, col = iy * box.nx; ix < box.nx; ++ix, ++col) {
            const ColumnTop& c = grid[col];
            if (c.z == -std::numeric_limits<float>::infinity()) continue;
            const float cx = box.x0 + (ix + 0.5f) / box.inv_leaf;
            const int offset = radialOffset(cx, cy, box.nx);
            const float z_drop = c.z - min_dz;
            std::uint8_t flags = kFrontDrop | kBackDrop;  // at the robot itself: both
            if (offset != 0) {
                const float z_front = neighbourZ(grid, col, -offset);
                const float z_back = neighbourZ(grid, col, offset);
                // A drop on one side with a higher column on the other side is the top of a
                // riser just below the real nosing (noise spill): not a nosing.
                const float z_spill = c.z + spill_dz;
                flags = (z_front < z_drop && !(z_back > z_spill) ? kFrontDrop : 0) |
                        (z_back < z_drop && !(z_front > z_spill) ? kBackDrop : 0);
            }
            if (flags != 0) cells.push_back({c.x, c.y, c.z, flags});
        }
    }
}

}  // namespace stairmap
