#include "core/TopView.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#ifdef __SSE__
#include <xmmintrin.h>
#endif
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace stairmap {
namespace {

struct GridBox {
    float x0 = 0, y0 = 0;  // lower corner
    int nx = 0, ny = 0;
    float inv_leaf = 0;
};

/// Running XY bounds; `v < m ? v : m` keeps m when v is NaN.
struct XyBounds {
    float min_x = std::numeric_limits<float>::max(), min_y = min_x;
    float max_x = -min_x, max_y = -min_x;
    void add(float x, float y) {
        min_x = x < min_x ? x : min_x;
        max_x = x > max_x ? x : max_x;
        min_y = y < min_y ? y : min_y;
        max_y = y > max_y ? y : max_y;
    }
};

#ifdef __SSE__
/// Bounds of the first 4 * (n / 4) points with packed SSE: four points are 12 consecutive floats
/// (x y z x | y z x y | z x y z), so a running min/max per register position needs no shuffles;
/// the lanes are folded into x and y at the end. _mm_min_ps(v, m) returns m when v is NaN.
/// Returns how many points it covered. (The cheapest pass of the top view: 3 loads, 6 min/max
/// per 4 points, against ~20 scalar instructions per point.)
std::size_t boundsOfBlocks(const PointCloud& cloud, XyBounds& bounds) {
    static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "points are packed floats");
    const std::size_t blocks = cloud.size() / 4;
    if (blocks == 0) return 0;
    __m128 lo[3], hi[3];
    for (int r = 0; r < 3; ++r) {
        lo[r] = _mm_set1_ps(bounds.min_x);
        hi[r] = _mm_set1_ps(bounds.max_x);
    }
    const float* f = cloud.front().data();
    for (std::size_t b = 0; b < blocks; ++b, f += 12) {
        for (int r = 0; r < 3; ++r) {
            const __m128 v = _mm_loadu_ps(f + 4 * r);
            lo[r] = _mm_min_ps(v, lo[r]);
            hi[r] = _mm_max_ps(v, hi[r]);
        }
    }
    alignas(16) float l[12], h[12];
    for (int r = 0; r < 3; ++r) {
        _mm_store_ps(l + 4 * r, lo[r]);
        _mm_store_ps(h + 4 * r, hi[r]);
    }
    for (int j = 0; j + 1 < 12; j += 3) {  // j: an x position, j + 1 the y of the same point
        bounds.min_x = std::min(bounds.min_x, l[j]);
        bounds.min_y = std::min(bounds.min_y, l[j + 1]);
        bounds.max_x = std::max(bounds.max_x, h[j]);
        bounds.max_y = std::max(bounds.max_y, h[j + 1]);
    }
    return 4 * blocks;
}
#endif

/// Pass 1: bounding box of the finite points, limited to +-max_range (a cheap pass: the range and
/// height tests are left to pass 2), padded by `pad` empty columns on every side so that radial
/// neighbour look-ups never leave the grid.
GridBox boundingGrid(const PointCloud& cloud, const TopViewParams& p, int pad) {
    XyBounds bounds;
    std::size_t i = 0;
#ifdef __SSE__
    i = boundsOfBlocks(cloud, bounds);
#endif
    for (; i < cloud.size(); ++i) bounds.add(cloud[i].x(), cloud[i].y());
    float minx = bounds.min_x, miny = bounds.min_y, maxx = bounds.max_x, maxy = bounds.max_y;
    const float range = static_cast<float>(p.max_range_m);
    minx = std::max(minx, -range);
    miny = std::max(miny, -range);
    maxx = std::min(maxx, range);
    maxy = std::min(maxy, range);
    GridBox box;
    if (minx > maxx || miny > maxy) return box;
    box.inv_leaf = static_cast<float>(1.0 / p.leaf_m);
    // Grid aligned to multiples of the leaf so cells do not depend on the cloud's extent.
    box.x0 = (std::floor(minx * box.inv_leaf) - pad) / box.inv_leaf;
    box.y0 = (std::floor(miny * box.inv_leaf) - pad) / box.inv_leaf;
    box.nx = static_cast<int>((maxx - box.x0) * box.inv_leaf) + 1 + pad;
    box.ny = static_cast<int>((maxy - box.y0) * box.inv_leaf) + 1 + pad;
    return box;
}

/// Longest walk of empty columns (and grid padding) for the neighbour look-up; the walk itself is
/// TopViewParams::neighbour_walk_m (DetectorParams documents the choice).
constexpr int kPad = kMaxNeighbourWalk;

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
constexpr float kFraction = 65536.f;       ///< position steps per leaf

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

/// Pass 2: the highest point of every column.
void highestPoints(const PointCloud& cloud, const TopViewParams& p, const GridBox& box,
                   const HeightCode& code, Column* grid, std::uint8_t* written) {
    const float r2 = static_cast<float>(p.max_range_m * p.max_range_m);
    const float lo = static_cast<float>(p.z_lo), hi = static_cast<float>(p.z_hi);
    // The range test is needed only when a corner of the box lies beyond max_range (indoors the
    // whole box is usually within it).
    const float far_x = std::max(std::abs(box.x0), std::abs(box.x0 + box.nx / box.inv_leaf));
    const float far_y = std::max(std::abs(box.y0), std::abs(box.y0 + box.ny / box.inv_leaf));
    const bool check_range = far_x * far_x + far_y * far_y > r2;
    // Points lie at least kPad columns inside the padded box; the test guards the neighbour
    // look-ups and drops non-finite coordinates before the conversion to int.
    const float g_lo = kPad, gx_hi = static_cast<float>(box.nx - kPad);
    const float gy_hi = static_cast<float>(box.ny - kPad);
    for (const auto& q : cloud) {
        const float gx = (q.x() - box.x0) * box.inv_leaf, gy = (q.y() - box.y0) * box.inv_leaf;
        // Bitwise & of the tests (no short-circuit branches); NaN fails every comparison.
        bool keep = (q.z() >= lo) & (q.z() <= hi) & (gx >= g_lo) & (gx < gx_hi) & (gy >= g_lo) &
                    (gy < gy_hi);
        if (check_range) keep &= q.x() * q.x() + q.y() * q.y() <= r2;
        // A dropped point (possibly NaN: never converted to int) updates a valid column with the
        // empty word, which the max ignores.
        const float sx = keep ? gx : g_lo, sy = keep ? gy : g_lo, sz = keep ? q.z() : lo;
        const int ix = static_cast<int>(sx), iy = static_cast<int>(sy);
        const auto z_q = static_cast<std::uint64_t>(std::min(code.encode(sz), kMaxQuanta));
        // sx - ix is sx's fractional part, exact in float and below 1, so times 2^16 it stays
        // below 65536: no clamp needed.
        const auto fx = static_cast<std::uint64_t>(static_cast<int>((sx - ix) * kFraction));
        const auto fy = static_cast<std::uint64_t>(static_cast<int>((sy - iy) * kFraction));
        const std::uint64_t word = keep ? (z_q << 32 | fx << 16 | fy) : 0u;
        const int col = iy * box.nx + ix;
        grid[col].bits = std::max(grid[col].bits, word);
        written[col >> kSegmentShift] = 1;
    }
}

/// True when all 8 neighbours are occupied and lie within [z_lo, z_hi): then the nearest column
/// on both radial sides is one of them (a unit direction always rounds to a neighbour), neither
/// side drops, and the column is no candidate. Cheap exact shortcut for dense surfaces.
inline bool flatNeighbourhood(const Column* grid, int col, int nx, int z_lo, int z_hi) {
    const int around[8] = {-nx - 1, -nx, -nx + 1, -1, 1, nx - 1, nx, nx + 1};
    z_lo = std::max(z_lo, 1);  // an empty column (0) is never flat
    for (int d : around) {
        const int z = grid[col + d].z_q();
        if (z < z_lo || z >= z_hi) return false;
    }
    return true;
}

/// Grid offsets of the columns 1..kPad leaves away from the robot along the exact radial direction
/// at (x, y) (the opposite offsets go towards the robot). Returns false at the robot itself.
bool radialOffsets(float x, float y, int nx, int (&offsets)[kPad]) {
    const float r2 = x * x + y * y;
    if (r2 < 1e-12f) return false;
    const float inv_r = 1.0f / std::sqrt(r2);
    const float ux = x * inv_r, uy = y * inv_r;
    // Rounding by truncation after shifting |v| <= kPad to positive values (std::floor is a libm
    // call without SSE4.1); halves round up.
    constexpr float kShift = 0.5f + kPad + 1;
#ifdef __SSE2__
    // Four offsets at a time (a tenth of the top view when scalar). Rounded steps are small
    // integers, so step_y * nx + step_x is exact in float.
    static_assert(kPad % 4 == 0, "offsets come in fours");
    const __m128 shift = _mm_set1_ps(kShift), ux4 = _mm_set1_ps(ux), uy4 = _mm_set1_ps(uy);
    const __m128 nx4 = _mm_set1_ps(static_cast<float>(nx));
    const __m128 whole = _mm_set1_ps(kPad + 1);
    for (int k = 0; k < kPad; k += 4) {
        const __m128 steps = _mm_setr_ps(k + 1.f, k + 2.f, k + 3.f, k + 4.f);
        auto rounded = [&](__m128 u) {
            const __m128i t = _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(steps, u), shift));
            return _mm_sub_ps(_mm_cvtepi32_ps(t), whole);
        };
        const __m128 off = _mm_add_ps(_mm_mul_ps(rounded(uy4), nx4), rounded(ux4));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(offsets + k), _mm_cvtps_epi32(off));
    }
#else
    auto round = [](float v) { return static_cast<int>(v + kShift) - (kPad + 1); };
    for (int k = 0; k < kPad; ++k) offsets[k] = round((k + 1) * uy) * nx + round((k + 1) * ux);
#endif
    return true;
}

/// What lies next to a column along one radial direction (heights in quanta, 0 = nothing).
struct Neighbourhood {
    bool drop = false;  ///< a lower surface (or nothing) follows
    int first_z = 0;    ///< nearest occupied column
};

/// Walks up to `walk` (<= kPad) columns along the offsets (sign -1: towards the robot). Empty columns of a
/// sparse cloud are skipped; nothing at all counts as a drop; a much higher column (a wall beside
/// the edge's end) is looked past; a column at about the same level ends the walk without a drop.
inline Neighbourhood inspect(const Column* grid, int col, const int (&offsets)[kPad], int walk,
                             int sign, int z_drop, int z_wall) {
    Neighbourhood n;
    for (int k = 0; k < walk; ++k) {
        const int z = grid[col + sign * offsets[k]].z_q();
        if (z == 0) continue;
        if (n.first_z == 0) n.first_z = z;
        if (z < z_drop) {
            n.drop = true;
            return n;
        }
        if (z < z_wall) return n;
    }
    n.drop = n.first_z == 0;
    return n;
}

/// Thresholds of the classification, in height quanta.
struct Thresholds {
    int min_dz, spill_dz, spill_max, ground_lo, ground_hi;
    int walk;  ///< columns of the neighbour walk, 1..kPad
};

/// Quanta of a height that may lie outside [z_lo, z_hi] (clamped to 0 .. kMaxQuanta + 1).
int codeClamped(const HeightCode& code, double z) {
    const double q = 1.0 + (z - code.z_lo) / code.step;
    return static_cast<int>(std::clamp(q, 0.0, kMaxQuanta + 1.0));
}

/// Candidate flags of an occupied column (0: not a nosing candidate).
std::uint8_t classify(const Column* grid, int col, int nx, float cx, float cy,
                      const Thresholds& t) {
    const int z = grid[col].z_q();
    if (flatNeighbourhood(grid, col, nx, z - t.min_dz, z + t.spill_max)) return 0;
    int offsets[kPad];
    if (!radialOffsets(cx, cy, nx, offsets)) return kFrontDrop | kBackDrop;  // at the robot
    const int z_drop = z - t.min_dz, lo = z + t.spill_dz, hi = z + t.spill_max;
    const bool ground = z > t.ground_lo && z < t.ground_hi;
    Neighbourhood front;  // not needed in the ground band: no drop, no spill
    if (!ground) front = inspect(grid, col, offsets, t.walk, -1, z_drop, hi);
    const Neighbourhood back = inspect(grid, col, offsets, t.walk, +1, z_drop, hi);
    // A drop on one side with a slightly higher column on the other side is the top of a riser
    // just below the real nosing (noise spill): not a nosing. A much higher column (a wall, the
    // floor above) does not count.
    const bool back_spill = back.first_z > lo && back.first_z < hi;
    const bool front_spill = front.first_z > lo && front.first_z < hi;
    return (front.drop && !back_spill ? kFrontDrop : 0) |
           (back.drop && !front_spill ? kBackDrop : 0);
}

/// Clears the first `segments` segments' marked columns and their marks when buildTopView returns
/// (or throws).
struct ClearOnExit {
    std::vector<Column>& grid;
    std::vector<std::uint8_t>& written;
    std::size_t segments;
    ~ClearOnExit() {
        const std::size_t n = grid.size();
        for (std::size_t s = 0; s < segments; ++s) {
            if (!written[s]) continue;
            const std::size_t first = s << kSegmentShift;
            Column* const segment = grid.data() + first;
            if (first + kSegment <= n) {  // a whole segment: fixed-size stores, no libc call
                for (int k = 0; k < kSegment; ++k) segment[k].bits = 0;
            } else {
                std::memset(segment, 0, (n - first) * sizeof(Column));
            }
        }
        std::memset(written.data(), 0, segments);
    }
};

/// Whether the 8 segment marks from `s` on are all clear (one 8-byte load).
inline bool eightClear(const std::uint8_t* marks, std::size_t s) {
    std::uint64_t word;
    std::memcpy(&word, marks + s, sizeof word);
    return word == 0;
}

}  // namespace

void buildTopView(const PointCloud& cloud, const TopViewParams& p,
                  std::vector<TopViewCell>& cells) {
    cells.clear();
    // One spare column beyond kPad: float rounding may put an extreme point one cell further out.
    const GridBox box = boundingGrid(cloud, p, kPad + 1);
    if (box.nx == 0) return;
    const HeightCode code(p.z_lo, p.z_hi);
    // Per-thread scratch grid and segment marks, re-used between calls (no page faults for fresh
    // memory) and all zero between calls: what a call writes it clears before it returns.
    thread_local std::vector<Column> tl_grid;
    thread_local std::vector<std::uint8_t> tl_written;
    std::vector<Column>& grid = tl_grid;
    std::vector<std::uint8_t>& written = tl_written;
    const std::size_t n = static_cast<std::size_t>(box.nx) * box.ny;
    const std::size_t segments = (n + kSegment - 1) >> kSegmentShift;
    // Grown, never shrunk: a vector grown again after a shrink zero-fills the difference, a
    // sixteenth of the top view's time when cloud extents alternate. Columns beyond n stay zero.
    if (grid.size() < n) grid.resize(n);
    if (written.size() < segments) written.resize(segments);
    const ClearOnExit clear{grid, written, segments};
    highestPoints(cloud, p, box, code, grid.data(), written.data());
    // Read through a local pointer: the scan's push_back could alias the thread-local vector, so
    // grid.data() would be loaded again (through the thread pointer) for every column.
    const Column* const columns = grid.data();
    const std::uint8_t* const marks = written.data();
    Thresholds t;
    t.min_dz = code.quanta(p.edge_min_dz_m);
    t.walk = std::clamp(static_cast<int>(std::lround(p.neighbour_walk_m / p.leaf_m)), 1, kPad);
    t.spill_dz = code.quanta(p.edge_spill_dz_m);
    t.spill_max = code.quanta(p.edge_spill_max_dz_m);
    t.ground_lo = codeClamped(code, p.ground_z_lo);
    t.ground_hi = codeClamped(code, p.ground_z_hi);
    const float leaf = 1.0f / box.inv_leaf;
    // Marked segments only, in memory (row-major) order; the row follows the column index.
    int iy = 0;
    std::size_t row_start = 0;
    for (std::size_t s = 0; s < segments; ++s) {
        if ((s & 7) == 0 && s + 8 <= segments && eightClear(marks, s)) {  // most are empty
            s += 7;
            continue;
        }
        if (!marks[s]) continue;
        const std::size_t end = std::min((s + 1) << kSegmentShift, n);
        for (std::size_t col = s << kSegmentShift; col < end; ++col) {
            const Column c = columns[col];
            if (c.bits == 0) continue;
            while (col >= row_start + static_cast<std::size_t>(box.nx)) {
                row_start += box.nx;
                ++iy;
            }
            const int ix = static_cast<int>(col - row_start);
            // Direction from the robot, taken at the column centre (grid-aligned, no point noise).
            const float cx = box.x0 + (ix + 0.5f) * leaf, cy = box.y0 + (iy + 0.5f) * leaf;
            const std::uint8_t flags = classify(columns, static_cast<int>(col), box.nx, cx, cy, t);
            if (flags == 0) continue;
            cells.push_back({box.x0 + (ix + (c.fx() + 0.5f) / kFraction) * leaf,
                             box.y0 + (iy + (c.fy() + 0.5f) / kFraction) * leaf,
                             code.decode(c.z_q()), flags});
        }
    }
}

}  // namespace stairmap
