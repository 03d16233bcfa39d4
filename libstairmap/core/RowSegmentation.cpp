#include "core/RowSegmentation.h"

#include <cmath>
#include <utility>

#include "core/LineFit.h"

namespace stairmap {
namespace {

using Range = std::pair<int, int>;  // inclusive point indices

struct RowBuffer {
    std::vector<float> x, y, z;
    RowPointView view() const { return {x.data(), y.data(), z.data()}; }
};

float gap2(const float* x, const float* y, int i, int j) {
    const float dx = x[i] - x[j], dy = y[i] - y[j];
    return dx * dx + dy * dy;
}

/// Iterative end-point fit on [first, last]: splits at the farthest point from the chord while it
/// is farther than d_p. The split point goes to both halves so no end point is dropped.
void splitChain(const RowBuffer& b, Range chain, double d_p, std::vector<Range>& out) {
    thread_local std::vector<Range> tl_stack;  // scratch re-used between calls
    std::vector<Range>& stack = tl_stack;
    stack.assign(1, chain);
    while (!stack.empty()) {
        const Range r = stack.back();
        stack.pop_back();
        const double ax = b.x[r.first], ay = b.y[r.first];
        const double dx = b.x[r.second] - ax, dy = b.y[r.second] - ay;
        const double len = std::sqrt(dx * dx + dy * dy);
        int worst = -1;
        if (len > 1e-9) {
            // distance * len = |cross|: the farthest point without a division per point
            double worst_cross = d_p * len;
            for (int i = r.first + 1; i < r.second; ++i) {
                const double cross = std::abs((b.x[i] - ax) * dy - (b.y[i] - ay) * dx);
                if (cross > worst_cross) {
                    worst_cross = cross;
                    worst = i;
                }
            }
        } else {  // a closed loop: distances to the common end point
            double worst_d2 = d_p * d_p;
            for (int i = r.first + 1; i < r.second; ++i) {
                const double px = b.x[i] - ax, py = b.y[i] - ay;
                if (px * px + py * py > worst_d2) {
                    worst_d2 = px * px + py * py;
                    worst = i;
                }
            }
        }
        if (worst < 0) {
            out.push_back(r);
            continue;
        }
        stack.push_back({worst, r.second});  // processed after the left half: keeps order
        stack.push_back({r.first, worst});
    }
}

/// Fits every range and merges neighbours whose lines agree (paper: merging with the covariances).
void fitAndMerge(const RowBuffer& b, const std::vector<Range>& parts, const SegmentationParams& p,
                 std::vector<LineSegment>& lines) {
    const RowPointView v = b.view();
    bool have = false;
    Range cur{};
    LineSegment cur_fit;
    auto flush = [&]() {
        if (have && cur.second - cur.first + 1 >= p.min_line_points &&
            cur_fit.length() >= p.min_line_length_m) {
            lines.push_back(cur_fit);
        }
    };
    for (const Range& r : parts) {
        if (r.second - r.first + 1 < 2) continue;
        const LineSegment f = fitLine(v, r.first, r.second, p.point_sigma_m);
        if (have && r.first == cur.second && lineMahalanobis2(cur_fit, f) < p.merge_chi2) {
            cur.second = r.second;
            cur_fit = fitLine(v, cur.first, cur.second, p.point_sigma_m);
            continue;
        }
        flush();
        cur = r;
        cur_fit = f;
        have = true;
    }
    flush();
}

void segmentLinear(const RowBuffer& b, const SegmentationParams& p,
                   std::vector<LineSegment>& lines) {
    const int n = static_cast<int>(b.x.size());
    const float max_gap2 = static_cast<float>(p.max_point_gap_m * p.max_point_gap_m);
    thread_local std::vector<Range> tl_parts;  // scratch re-used between calls
    std::vector<Range>& parts = tl_parts;
    int chain_start = 0;
    for (int i = 1; i <= n; ++i) {
        if (i < n && gap2(b.x.data(), b.y.data(), i - 1, i) <= max_gap2) continue;
        // One chain at a time: lines never bridge a gap, and a chain too short for a line is
        // not fitted at all.
        if (i - chain_start >= p.min_line_points) {
            parts.clear();
            splitChain(b, {chain_start, i - 1}, p.split_distance_m, parts);
            fitAndMerge(b, parts, p, lines);
        }
        chain_start = i;
    }
}

/// True when point i lies farther than d from the chord through points a and b (compared in
/// squares: no square root or division per point).
bool fartherFromChord(const float* x, const float* y, int a, int i, int b, float d) {
    const float dx = x[b] - x[a], dy = y[b] - y[a];
    const float px = x[i] - x[a], py = y[i] - y[a];
    const float len2 = dx * dx + dy * dy;
    if (!(len2 > 1e-12f)) return px * px + py * py > d * d;  // a and b coincide
    const float cross = px * dy - py * dx;
    return cross * cross > d * d * len2;
}

/// Copies the row starting at `start` (circularly), dropping single-point spikes: a point far
/// from the chord of its two neighbours that are themselves close (an isolated noisy edge column
/// behind the nosing would otherwise cut the line in two and cost it its end points).
void rotateInto(const float* x, const float* y, const float* z, int n, int start, double d_p,
                double max_gap, RowBuffer& b) {
    b.x.clear();
    b.y.clear();
    b.z.clear();
    const float max_gap2 = static_cast<float>(max_gap * max_gap);
    const float d_p_f = static_cast<float>(d_p);
    // prev, i, next walk the ring together (no modulo per point: it is an integer division).
    int prev = start == 0 ? n - 1 : start - 1, i = start;
    for (int k = 0; k < n; ++k) {
        const int next = i + 1 == n ? 0 : i + 1;
        const bool spike = k > 0 && k + 1 < n && gap2(x, y, prev, next) <= max_gap2 &&
                           fartherFromChord(x, y, prev, i, next, d_p_f);
        if (!spike) {
            b.x.push_back(x[i]);
            b.y.push_back(y[i]);
            b.z.push_back(z[i]);
        }
        prev = i;
        i = next;
    }
}

}  // namespace

void segmentCircularRow(const float* x, const float* y, const float* z, int n,
                        const SegmentationParams& p, std::vector<LineSegment>& lines) {
    if (n < p.min_line_points) return;
    const float max_gap2 = static_cast<float>(p.max_point_gap_m * p.max_point_gap_m);
    // Start the row just after a gap so that no line straddles the start (the +-180 deg seam).
    int start = -1;
    for (int k = 0; k < n && start < 0; ++k) {
        if (gap2(x, y, (k + n - 1) % n, k) > max_gap2) start = k;
    }
    // Per-thread scratch re-used between rows and calls: rows are many and short.
    thread_local RowBuffer tl_buffer, tl_ring;
    RowBuffer& b = tl_buffer;
    if (start >= 0) {
        rotateInto(x, y, z, n, start, p.split_distance_m, p.max_point_gap_m, b);
        segmentLinear(b, p, lines);
        return;
    }
    // A closed ring without gaps: restart it at a corner found by a first split.
    rotateInto(x, y, z, n, 0, p.split_distance_m, p.max_point_gap_m, b);
    std::vector<Range> parts;
    splitChain(b, {0, static_cast<int>(b.x.size()) - 1}, p.split_distance_m, parts);
    const int shift = parts.size() > 1 ? parts[1].first : 0;
    RowBuffer& ring = tl_ring;
    ring.x.clear();
    ring.y.clear();
    ring.z.clear();
    const int m = static_cast<int>(b.x.size());
    for (int k = 0; k < m; ++k) {
        ring.x.push_back(b.x[(shift + k) % m]);
        ring.y.push_back(b.y[(shift + k) % m]);
        ring.z.push_back(b.z[(shift + k) % m]);
    }
    segmentLinear(ring, p, lines);
}

void segmentRows(const CylindricalRows& rows, const SegmentationParams& p,
                 std::vector<LineSegment>& lines) {
    for (std::size_t r = 0; r + 1 < rows.row_begin.size(); ++r) {
        const int b = rows.row_begin[r];
        const int n = rows.row_begin[r + 1] - b;
        segmentCircularRow(rows.x.data() + b, rows.y.data() + b, rows.z.data() + b, n, p, lines);
    }
}

}  // namespace stairmap
