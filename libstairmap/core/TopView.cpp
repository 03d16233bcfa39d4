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

constexpr float kEmpty = -std::numeric_limits<float>::infinity();  ///< z of an empty column
constexpr int kPad = 3;  ///< empty columns skipped (and grid padding) for the neighbour look-up

/// Pass 2: the highest point of every column: its z (grid_z, the hot 4-byte array that the random
/// updates of an unordered cloud hit) and its index in the cloud (written only on an update).
void highestPoints(const PointCloud& cloud, const TopViewParams& p, const GridBox& box,
                   float* grid_z, int* grid_index) {
    const float r2 = static_cast<float>(p.max_range_m * p.max_range_m);
    const float lo = static_cast<float>(p.z_lo), hi = static_cast<float>(p.z_hi);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const auto& q = cloud[i];
        if (!usable(q, r2, lo, hi)) continue;
        const int ix = static_cast<int>((q.x() - box.x0) * box.inv_leaf);
        const int iy = static_cast<int>((q.y() - box.y0) * box.inv_leaf);
        const int c = std::clamp(iy, 1, box.ny - 2) * box.nx + std::clamp(ix, 1, box.nx - 2);
        if (q.z() > grid_z[c]) {
            grid_z[c] = q.z();
            grid_index[c] = static_cast<int>(i);
        }
    }
}

/// Grid offsets of the columns 1..kPad leaves away from the robot along the exact radial direction
/// at (x, y) (the opposite offsets go towards the robot). Returns false at the robot itself.
bool radialOffsets(float x, float y, int nx, int (&offsets)[kPad]) {
    const float r2 = x * x + y * y;
    if (r2 < 1e-12f) return false;
    const float inv_r = 1.0f / std::sqrt(r2);
    const float ux = x * inv_r, uy = y * inv_r;
    // Rounding by truncation of +-0.5 (std::floor is a libm call without SSE4.1).
    auto round = [](float v) { return static_cast<int>(v + (v >= 0.f ? 0.5f : -0.5f)); };
    for (int k = 0; k < kPad; ++k) offsets[k] = round((k + 1) * uy) * nx + round((k + 1) * ux);
    return true;
}

/// What lies next to a column along one radial direction.
struct Neighbourhood {
    bool drop = false;  ///< a lower surface (or nothing) follows
    float first_z = -std::numeric_limits<float>::infinity();  ///< nearest occupied column
};

/// Walks up to kPad columns along the offsets (sign -1: towards the robot). Empty columns of a
/// sparse cloud are skipped; nothing at all counts as a drop; a much higher column (a wall beside
/// the edge's end) is looked past; a column at about the same level ends the walk without a drop.
inline Neighbourhood inspect(const float* grid_z, int col, const int (&offsets)[kPad], int sign,
                             float z_drop, float z_wall) {
    Neighbourhood n;
    bool seen = false;
    for (int k = 0; k < kPad; ++k) {
        const float z = grid_z[col + sign * offsets[k]];
        if (z == kEmpty) continue;
        if (!seen) n.first_z = z;
        seen = true;
        if (z < z_drop) {
            n.drop = true;
            return n;
        }
        if (z < z_wall) return n;
    }
    n.drop = !seen;
    return n;
}

}  // namespace

void buildTopView(const PointCloud& cloud, const TopViewParams& p, std::vector<TopViewCell>& cells) {
    cells.clear();
    // One spare column beyond kPad: float rounding may put an extreme point one cell further out.
    const GridBox box = boundingGrid(cloud, p, kPad + 1);
    if (box.nx == 0) return;
    const std::size_t ncols = static_cast<std::size_t>(box.nx) * box.ny;
    // Per-thread scratch grids: re-used between calls, so no page faults for fresh memory.
    thread_local std::vector<float> tl_z;
    thread_local std::vector<int> tl_index;
    std::vector<float>& z_store = tl_z;
    std::vector<int>& index_store = tl_index;
    z_store.assign(ncols, kEmpty);
    index_store.resize(ncols);  // only read where z is set
    highestPoints(cloud, p, box, z_store.data(), index_store.data());
    const float* grid_z = z_store.data();
    const float min_dz = static_cast<float>(p.edge_min_dz_m);
    const float leaf = 1.0f / box.inv_leaf;
    const float ground_lo = static_cast<float>(p.ground_z_lo);
    const float ground_hi = static_cast<float>(p.ground_z_hi);
    const float spill_dz = static_cast<float>(p.edge_spill_dz_m);
    const float spill_max = static_cast<float>(p.edge_spill_max_dz_m);
    for (int iy = 0; iy < box.ny; ++iy) {
        // Direction from the robot, taken at the column centre (grid-aligned, no point noise).
        const float cy = box.y0 + (iy + 0.5f) * leaf;
        for (int ix = 0, col = iy * box.nx; ix < box.nx; ++ix, ++col) {
            const float z = grid_z[col];
            if (z == kEmpty) continue;
            const float cx = box.x0 + (ix + 0.5f) * leaf;
            int offsets[kPad];
            const bool away = radialOffsets(cx, cy, box.nx, offsets);
            const float z_drop = z - min_dz;
            std::uint8_t flags = kFrontDrop | kBackDrop;  // at the robot itself: both
            if (away) {
                const float lo = z + spill_dz, hi = z + spill_max;
                const bool ground = z > ground_lo && z < ground_hi;
                Neighbourhood front;  // not needed in the ground band: no drop, no spill
                if (!ground) front = inspect(grid_z, col, offsets, -1, z_drop, hi);
                const Neighbourhood back = inspect(grid_z, col, offsets, +1, z_drop, hi);
                // A drop on one side with a slightly higher column on the other side is the top of
                // a riser just below the real nosing (noise spill): not a nosing. A much higher
                // column (a wall, the floor above) does not count.
                const bool back_spill = back.first_z > lo && back.first_z < hi;
                const bool front_spill = front.first_z > lo && front.first_z < hi;
                flags = (front.drop && !back_spill ? kFrontDrop : 0) |
                        (back.drop && !front_spill ? kBackDrop : 0);
            }
            if (flags == 0) continue;
            const Eigen::Vector3f& q = cloud[index_store[col]];
            cells.push_back({q.x(), q.y(), z, flags});
        }
    }
}

}  // namespace stairmap
