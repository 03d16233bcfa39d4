#include "core/TopView.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "core/TopViewGrid.h"

namespace stairmap {
namespace {

using topview::boundingGrid;
using topview::Column;
using topview::GridBox;
using topview::HeightCode;
using topview::highestPoints;
using topview::kFraction;
using topview::kMaxQuanta;
using topview::kSegment;
using topview::kSegmentShift;

/// Longest walk of empty columns (and grid padding) for the neighbour look-up; the walk itself is
/// TopViewParams::neighbour_walk_m (DetectorParams documents the choice).
constexpr int kPad = kMaxNeighbourWalk;

/// True when all 8 neighbours are occupied and lie within [z_lo, z_hi): then the nearest column
/// on both radial sides is one of them (a unit direction always rounds to a neighbour), neither
/// side drops, and the column is no candidate. Exact; asked only where the first radial step
/// lies too near a rounding boundary to be told from squares (firstRadialStep).
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

/// A column centre's coordinate along one grid axis [m], its square, and the grid offset of one
/// column outward (away from the robot) along that axis.
struct AxisCentre {
    float c = 0, c2 = 0;
    int step = 0;
};

AxisCentre axisCentre(float c, int unit) { return {c, c * c, c > 0 ? unit : -unit}; }

/// Grid offset of the first column of the radial walk away from the robot (offsets[0] of
/// radialOffsets), found without the direction's square root when it is clear: the larger of
/// |x|, |y| always steps (its unit component is at least 0.707), the smaller one steps when its
/// unit component is at least a half, i.e. 3 min^2 >= max^2. Returns false when that comparison
/// lies within float rounding of the boundary (radialOffsets decides then).
inline bool firstRadialStep(const AxisCentre& x, const AxisCentre& y, int& step) {
    const bool x_major = x.c2 >= y.c2;
    const float major = x_major ? x.c2 : y.c2, minor3 = 3.0f * (x_major ? y.c2 : x.c2);
    constexpr float kMargin = 1e-4f;  // relative; float rounding of the unit vector is ~1e-7
    if (std::abs(minor3 - major) <= kMargin * major || major < 1e-12f) return false;
    const bool minor_steps = minor3 > major;
    step = (x_major || minor_steps ? x.step : 0) + (!x_major || minor_steps ? y.step : 0);
    return true;
}

/// Candidate flags of an occupied column (0: not a nosing candidate).
std::uint8_t classify(const Column* grid, int col, int nx, const AxisCentre& x, const AxisCentre& y,
                      const Thresholds& t) {
    const int z = grid[col].z_q();
    const int z_drop = z - t.min_dz, lo = z + t.spill_dz, hi = z + t.spill_max;
    const bool ground = z > t.ground_lo && z < t.ground_hi;
    // Shortcut (half of all columns): a walk whose first column is occupied at about the same
    // level stops there without a drop; when that holds away from the robot (and, outside the
    // ground band, towards it) no side drops and the column is no candidate. It holds on every
    // flat column, so the 8-neighbour test is left to the rare undecided first steps.
    int step;
    if (firstRadialStep(x, y, step)) {
        const int level_lo = std::max(z_drop, 1);
        auto level = [&](int c) {
            const int zc = grid[c].z_q();
            return zc >= level_lo && zc < hi;
        };
        if (level(col + step) && (ground || level(col - step))) return 0;
    } else if (flatNeighbourhood(grid, col, nx, z_drop, hi)) {
        return 0;
    }
    int offsets[kPad];
    if (!radialOffsets(x.c, y.c, nx, offsets)) return kFrontDrop | kBackDrop;  // at the robot
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

/// Bit k set when column k of the 8 from `c` is occupied (a kept point has z_q >= 1).
inline unsigned occupiedColumns(const Column* c) {
    static_assert(kSegment == 8, "one mask byte per segment");
#ifdef __SSE2__
    const float* f = reinterpret_cast<const float*>(c);
    auto highs = [&](int k) {  // the z_q words (high halves) of columns k .. k + 3
        return _mm_castps_si128(_mm_shuffle_ps(_mm_loadu_ps(f + 2 * k), _mm_loadu_ps(f + 2 * k + 4),
                                               _MM_SHUFFLE(3, 1, 3, 1)));
    };
    const __m128i zero = _mm_setzero_si128();
    const unsigned empty_lo = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(highs(0), zero)));
    const unsigned empty_hi = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(highs(4), zero)));
    return ~(empty_lo | empty_hi << 4) & 0xffu;
#else
    unsigned m = 0;
    for (int k = 0; k < kSegment; ++k) m |= static_cast<unsigned>(c[k].bits != 0) << k;
    return m;
#endif
}

/// Clears the first `segments` segments' marked columns and their marks when buildTopView returns
/// (or throws).
struct ClearOnExit {
    std::vector<Column>& grid;
    std::vector<std::uint8_t>& written;
    std::size_t segments;
    ~ClearOnExit() {
        for (std::size_t s = 0; s < segments; ++s) {
            if (!written[s]) continue;
            Column* const segment = grid.data() + (s << kSegmentShift);
            for (int k = 0; k < kSegment; ++k) segment[k].bits = 0;  // fixed-size stores
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
    // Whole segments (the scan reads all 8 columns of one at once), grown, never shrunk: a vector
    // grown again after a shrink zero-fills the difference, a sixteenth of the top view's time
    // when cloud extents alternate. Columns beyond n stay zero: no point lands there.
    if (grid.size() < segments * kSegment) grid.resize(segments * kSegment);
    if (written.size() < segments) written.resize(segments);
    const ClearOnExit clear{grid, written, segments};
    highestPoints(cloud, p, box, code, kPad, grid.data(), written.data());
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
    // Column centres' x by grid column (the direction from the robot is taken at the centre:
    // grid-aligned, no point noise).
    thread_local std::vector<AxisCentre> tl_centre_x;
    tl_centre_x.resize(box.nx);
    for (int ix = 0; ix < box.nx; ++ix)
        tl_centre_x[ix] = axisCentre(box.x0 + (ix + 0.5f) * leaf, 1);
    const AxisCentre* const centre_x = tl_centre_x.data();
    // Marked segments only, in memory (row-major) order, their occupied columns picked from a
    // bit mask (testing each column was an unpredictable branch); the row follows the column
    // index.
    int iy = 0;
    std::size_t row_start = 0;
    AxisCentre centre_y = axisCentre(box.y0 + 0.5f * leaf, box.nx);
    for (std::size_t s = 0; s < segments; ++s) {
        if ((s & 7) == 0 && s + 8 <= segments && eightClear(marks, s)) {  // most are empty
            s += 7;
            continue;
        }
        if (!marks[s]) continue;
        const std::size_t first = s << kSegmentShift;
        unsigned occupied = occupiedColumns(columns + first);
        while (occupied) {
            const std::size_t col = first + __builtin_ctz(occupied);
            occupied &= occupied - 1;
            while (col >= row_start + static_cast<std::size_t>(box.nx)) {
                row_start += box.nx;
                ++iy;
                centre_y = axisCentre(box.y0 + (iy + 0.5f) * leaf, box.nx);
            }
            const int ix = static_cast<int>(col - row_start);
            const std::uint8_t flags =
                classify(columns, static_cast<int>(col), box.nx, centre_x[ix], centre_y, t);
            if (flags == 0) continue;
            const Column c = columns[col];
            cells.push_back({box.x0 + (ix + (c.fx() + 0.5f) / kFraction) * leaf,
                             box.y0 + (iy + (c.fy() + 0.5f) / kFraction) * leaf,
                             code.decode(c.z_q()), flags});
        }
    }
}

}  // namespace stairmap
