#pragma once
// The top view's grid (paper Sec. III-A, first step): for every leaf x leaf XY column, the
// highest point, in one flat array over the points' bounding box (no hashing, no sorting).
// Internal to the top view (TopView.cpp); TopView.h describes the whole step.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/PointCloud.h"
#include "core/TopView.h"

namespace stairmap::topview {

/// The grid's placement: lower corner [m], size in columns, columns per metre.
struct GridBox {
    float x0 = 0, y0 = 0;  // lower corner
    int nx = 0, ny = 0;
    float inv_leaf = 0;
};

/// Pass 1: bounding box of the finite points, limited to +-max_range (a cheap pass: the range and
/// height tests are left to pass 2), padded by `pad` empty columns on every side so that radial
/// neighbour look-ups never leave the grid. nx == 0 when no point lies within range.
GridBox boundingGrid(const PointCloud& cloud, const TopViewParams& p, int pad);

/// One column of the grid in one 64-bit word: the highest point's height in quanta above z_lo in
/// the high 32 bits (0 = empty column; a quantum is 3 nm for a 6 m band), then its position inside
/// the column in 1/65536 of a leaf. "Keep the higher point" is then an unsigned max, free of
/// branches: whether a point is higher is unpredictable in a cloud, and mispredicted branches cost
/// a quarter of the pass. The grid stays small (a 10 m x 10 m area at 2.5 cm is 1.3 MB), the point
/// is never looked up again in the cloud, and equal heights (exact ties) keep the larger fx, fy.
struct Column {
    std::uint64_t bits;
    int z_q() const { return static_cast<int>(bits >> 32); }
    int fx() const { return static_cast<int>((bits >> 16) & 0xffffu); }
    int fy() const { return static_cast<int>(bits & 0xffffu); }
};
constexpr int kMaxQuanta = (1 << 30) - 1;  ///< fits int arithmetic with the thresholds
/// Segments of 8 consecutive columns (in memory order) are marked when a point lands in one: the
/// scan skips unmarked ones with one byte test, and only marked ones are cleared afterwards, so a
/// wide grid (a LiDAR's 20 m box: 640k columns, 5 MB) costs neither a full memset nor a full read.
constexpr int kSegmentShift = 3;
constexpr int kSegment = 1 << kSegmentShift;
constexpr float kFraction = 65536.f;  ///< position steps per leaf

/// Height quantisation: z_q = 1 + (z - z_lo) / step, so 1..kMaxQuanta covers [z_lo, z_hi].
struct HeightCode {
    float z_lo = 0;
    double step = 1, inv_step = 1;
    HeightCode(double lo, double hi)
        : z_lo(static_cast<float>(lo)),
          step(std::max(hi - lo, 1e-3) / (kMaxQuanta - 1)),
          inv_step(1.0 / step) {}
    int encode(float z) const { return 1 + static_cast<int>((z - z_lo) * inv_step); }
    float decode(int z_q) const { return static_cast<float>(z_lo + (z_q - 0.5) * step); }
    int quanta(double dz) const { return static_cast<int>(std::lround(dz / step)); }
};

/// Pass 2: the highest point of every column into `grid` (nx * ny columns, all zero before), and
/// a mark in `written` for every segment of kSegment columns that received a point. Points
/// outside [z_lo, z_hi], beyond max_range, within `pad` columns of the box's border or not finite
/// are dropped. Four points at a time with SSE2 (the same words, bit for bit, as one at a time).
void highestPoints(const PointCloud& cloud, const TopViewParams& p, const GridBox& box,
                   const HeightCode& code, int pad, Column* grid, std::uint8_t* written);

}  // namespace stairmap::topview
