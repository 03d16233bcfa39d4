#include "core/TopViewGrid.h"

#include <limits>
#ifdef __SSE__
#include <xmmintrin.h>
#endif
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace stairmap::topview {
namespace {

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

/// What pass 2 keeps: heights within [z_lo, z_hi], grid coordinates (in leaves) within
/// [g_lo, gx_hi) x [g_lo, gy_hi), and, when check_range, XY ranges within sqrt(r2).
struct PassBounds {
    float z_lo, z_hi, r2, g_lo, gx_hi, gy_hi;
    bool check_range;
};

#ifdef __SSE2__
/// Pass 2 for the first 4 * (n / 4) points, four at a time: the same float and double operations
/// as the scalar loop in highestPoints (same words, bit for bit), the four column updates scalar.
/// Returns how many points it covered. (Scalar, the per-point arithmetic was three quarters of
/// the pass.)
std::size_t highestPointsOfBlocks(const PointCloud& cloud, const PassBounds& b, const GridBox& box,
                                  const HeightCode& code, Column* grid, std::uint8_t* written) {
    const std::size_t blocks = cloud.size() / 4;
    // The column index is one multiply-add of signed 16-bit pairs (below): ix, iy and nx must
    // stay below 2^15. DetectorParams' grid budget keeps them below 4096; larger grids go scalar.
    constexpr int kPairLimit = 1 << 15;
    if (blocks == 0 || box.nx >= kPairLimit || box.ny >= kPairLimit) return 0;
    const __m128 x0 = _mm_set1_ps(box.x0), y0 = _mm_set1_ps(box.y0);
    const __m128 inv_leaf = _mm_set1_ps(box.inv_leaf);
    const __m128 lo = _mm_set1_ps(b.z_lo), hi = _mm_set1_ps(b.z_hi), r2 = _mm_set1_ps(b.r2);
    const __m128 g_lo = _mm_set1_ps(b.g_lo), gx_hi = _mm_set1_ps(b.gx_hi);
    const __m128 gy_hi = _mm_set1_ps(b.gy_hi), fraction = _mm_set1_ps(kFraction);
    const __m128 code_lo = _mm_set1_ps(code.z_lo);
    const __m128d inv_step = _mm_set1_pd(code.inv_step);
    const __m128i one = _mm_set1_epi32(1), max_quanta = _mm_set1_epi32(kMaxQuanta);
    alignas(16) std::uint64_t words[4];
    alignas(16) std::int32_t cols[4];
    const __m128i row_pair = _mm_set1_epi32(box.nx << 16 | 1);
    const float* f = cloud.front().data();
    for (std::size_t blk = 0; blk < blocks; ++blk, f += 12) {
        // x y z x | y z x y | z x y z -> x, y, z of the four points
        const __m128 a = _mm_loadu_ps(f), m = _mm_loadu_ps(f + 4), c = _mm_loadu_ps(f + 8);
        const __m128 x = _mm_shuffle_ps(a, _mm_shuffle_ps(m, c, _MM_SHUFFLE(1, 1, 2, 2)),
                                        _MM_SHUFFLE(2, 0, 3, 0));
        const __m128 y =
            _mm_shuffle_ps(_mm_shuffle_ps(a, m, _MM_SHUFFLE(0, 0, 1, 1)),
                           _mm_shuffle_ps(m, c, _MM_SHUFFLE(2, 2, 3, 3)), _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 z =
            _mm_shuffle_ps(_mm_shuffle_ps(a, m, _MM_SHUFFLE(1, 1, 2, 2)),
                           _mm_shuffle_ps(c, c, _MM_SHUFFLE(3, 3, 0, 0)), _MM_SHUFFLE(2, 0, 2, 0));
        const __m128 gx = _mm_mul_ps(_mm_sub_ps(x, x0), inv_leaf);
        const __m128 gy = _mm_mul_ps(_mm_sub_ps(y, y0), inv_leaf);
        __m128 keep = _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(z, lo), _mm_cmple_ps(z, hi)),
                                 _mm_and_ps(_mm_cmpge_ps(gx, g_lo), _mm_cmplt_ps(gx, gx_hi)));
        keep = _mm_and_ps(keep, _mm_and_ps(_mm_cmpge_ps(gy, g_lo), _mm_cmplt_ps(gy, gy_hi)));
        if (b.check_range)
            keep =
                _mm_and_ps(keep, _mm_cmple_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), r2));
        auto select = [&](__m128 v, __m128 dropped) {
            return _mm_or_ps(_mm_and_ps(keep, v), _mm_andnot_ps(keep, dropped));
        };
        const __m128 sx = select(gx, g_lo), sy = select(gy, g_lo), sz = select(z, lo);
        const __m128i ix = _mm_cvttps_epi32(sx), iy = _mm_cvttps_epi32(sy);
        const __m128i fx =
            _mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(sx, _mm_cvtepi32_ps(ix)), fraction));
        const __m128i fy =
            _mm_cvttps_epi32(_mm_mul_ps(_mm_sub_ps(sy, _mm_cvtepi32_ps(iy)), fraction));
        // HeightCode::encode in double, two lanes at a time, then std::min with kMaxQuanta.
        const __m128 dz = _mm_sub_ps(sz, code_lo);
        const __m128i q_lo = _mm_cvttpd_epi32(_mm_mul_pd(_mm_cvtps_pd(dz), inv_step));
        const __m128i q_hi =
            _mm_cvttpd_epi32(_mm_mul_pd(_mm_cvtps_pd(_mm_movehl_ps(dz, dz)), inv_step));
        __m128i z_q = _mm_add_epi32(_mm_unpacklo_epi64(q_lo, q_hi), one);
        const __m128i over = _mm_cmpgt_epi32(z_q, max_quanta);
        z_q = _mm_or_si128(_mm_and_si128(over, max_quanta), _mm_andnot_si128(over, z_q));
        const __m128i kept = _mm_castps_si128(keep);
        const __m128i low = _mm_and_si128(kept, _mm_or_si128(_mm_slli_epi32(fx, 16), fy));
        z_q = _mm_and_si128(kept, z_q);
        _mm_store_si128(reinterpret_cast<__m128i*>(words), _mm_unpacklo_epi32(low, z_q));
        _mm_store_si128(reinterpret_cast<__m128i*>(words + 2), _mm_unpackhi_epi32(low, z_q));
        // col = iy * nx + ix: (ix, iy) . (1, nx) on 16-bit pairs.
        const __m128i pairs = _mm_or_si128(ix, _mm_slli_epi32(iy, 16));
        _mm_store_si128(reinterpret_cast<__m128i*>(cols), _mm_madd_epi16(pairs, row_pair));
        for (int k = 0; k < 4; ++k) {
            const int col = cols[k];
            grid[col].bits = std::max(grid[col].bits, words[k]);
            written[col >> kSegmentShift] = 1;
        }
    }
    return 4 * blocks;
}
#endif

}  // namespace

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

/// Pass 2: the highest point of every column.
void highestPoints(const PointCloud& cloud, const TopViewParams& p, const GridBox& box,
                   const HeightCode& code, int pad, Column* grid, std::uint8_t* written) {
    PassBounds b;
    b.r2 = static_cast<float>(p.max_range_m * p.max_range_m);
    b.z_lo = static_cast<float>(p.z_lo);
    b.z_hi = static_cast<float>(p.z_hi);
    // The range test is needed only when a corner of the box lies beyond max_range (indoors the
    // whole box is usually within it).
    const float far_x = std::max(std::abs(box.x0), std::abs(box.x0 + box.nx / box.inv_leaf));
    const float far_y = std::max(std::abs(box.y0), std::abs(box.y0 + box.ny / box.inv_leaf));
    b.check_range = far_x * far_x + far_y * far_y > b.r2;
    // Points lie at least `pad` columns inside the padded box; the test guards the neighbour
    // look-ups and drops non-finite coordinates before the conversion to int.
    b.g_lo = static_cast<float>(pad);
    b.gx_hi = static_cast<float>(box.nx - pad);
    b.gy_hi = static_cast<float>(box.ny - pad);
    std::size_t i = 0;
#ifdef __SSE2__
    i = highestPointsOfBlocks(cloud, b, box, code, grid, written);
#endif
    for (; i < cloud.size(); ++i) {
        const auto& q = cloud[i];
        const float gx = (q.x() - box.x0) * box.inv_leaf, gy = (q.y() - box.y0) * box.inv_leaf;
        // Bitwise & of the tests (no short-circuit branches); NaN fails every comparison.
        bool keep = (q.z() >= b.z_lo) & (q.z() <= b.z_hi) & (gx >= b.g_lo) & (gx < b.gx_hi) &
                    (gy >= b.g_lo) & (gy < b.gy_hi);
        if (b.check_range) keep &= q.x() * q.x() + q.y() * q.y() <= b.r2;
        // A dropped point (possibly NaN: never converted to int) updates a valid column with the
        // empty word, which the max ignores.
        const float sx = keep ? gx : b.g_lo, sy = keep ? gy : b.g_lo, sz = keep ? q.z() : b.z_lo;
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

}  // namespace stairmap::topview
