#include "core/CylindricalRows.h"

#include <algorithm>
#include <cmath>

namespace stairmap {

namespace {

/// One candidate entry of a row: azimuth bin, range and cell index.
struct Entry {
    int row, az;
    float range;
    int cell;
};

/// Counting sort of the entries by row (stable), O(n + rows).
void bucketByRow(const std::vector<Entry>& in, int nrows, std::vector<Entry>& out,
                 std::vector<int>& row_start) {
    row_start.assign(nrows + 1, 0);
    for (const Entry& e : in) ++row_start[e.row + 1];
    for (int r = 0; r < nrows; ++r) row_start[r + 1] += row_start[r];
    std::vector<int> fill(row_start.begin(), row_start.end() - 1);
    out.resize(in.size());
    for (const Entry& e : in) out[fill[e.row]++] = e;
}

}  // namespace

void buildCylindricalRows(const std::vector<TopViewCell>& cells, std::uint8_t flag,
                          const CylindricalParams& p, CylindricalRows& rows) {
    rows.x.clear();
    rows.y.clear();
    rows.z.clear();
    rows.azimuth.clear();
    rows.row_begin.clear();
    rows.azimuth_bins = p.azimuth_bins;
    const int nrows = static_cast<int>(std::ceil((p.z_hi - p.z_lo) / p.row_height_m));
    const float az_scale = static_cast<float>(p.azimuth_bins / (2 * M_PI));
    const float inv_row = static_cast<float>(1.0 / p.row_height_m);
    const float skip_lo = static_cast<float>(p.skip_z_lo), skip_hi = static_cast<float>(p.skip_z_hi);
    // Per-thread scratch, re-used between calls (no page faults on fresh memory).
    thread_local std::vector<Entry> tl_entries, tl_sorted;
    thread_local std::vector<int> tl_row_start;
    std::vector<Entry>& entries = tl_entries;
    std::vector<Entry>& sorted = tl_sorted;
    std::vector<int>& row_start = tl_row_start;
    entries.clear();
    for (int i = 0; i < static_cast<int>(cells.size()); ++i) {
        const TopViewCell& c = cells[i];
        if (!(c.flags & flag) || (c.z > skip_lo && c.z < skip_hi)) continue;
        // Row r spans [r - 0.5, r + 1.5) row heights: overlapping windows, so that an edge whose
        // points straddle a row boundary (noise) lies whole in at least one row.
        const float fr = (c.z - static_cast<float>(p.z_lo)) * inv_row;
        if (!(fr >= 0.f)) continue;
        const int row = static_cast<int>(fr);  // truncation == floor for fr >= 0
        const int other = (fr - row < 0.5f) ? row - 1 : row + 1;
        int az = static_cast<int>((std::atan2(c.y, c.x) + static_cast<float>(M_PI)) * az_scale);
        az = std::clamp(az, 0, p.azimuth_bins - 1);
        const float range = std::sqrt(c.x * c.x + c.y * c.y);
        for (int r : {row, other}) {
            if (r >= 0 && r < nrows) entries.push_back({r, az, range, i});
        }
    }
    bucketByRow(entries, nrows, sorted, row_start);
    // Per row: nearest entry per azimuth bin in a flat array; only the touched bins are read back
    // (sorted), so a sparse row costs its own size, not azimuth_bins.
    std::vector<int> nearest(p.azimuth_bins, -1);
    std::vector<int> touched;
    for (int r = 0; r < nrows; ++r) {
        if (row_start[r] == row_start[r + 1]) continue;
        touched.clear();
        for (int k = row_start[r]; k < row_start[r + 1]; ++k) {
            int& slot = nearest[sorted[k].az];
            if (slot < 0) touched.push_back(sorted[k].az);
            if (slot < 0 || sorted[k].range < sorted[slot].range) slot = k;
        }
        std::sort(touched.begin(), touched.end());
        rows.row_begin.push_back(static_cast<int>(rows.x.size()));
        for (int az : touched) {
            const TopViewCell& c = cells[sorted[nearest[az]].cell];
            rows.x.push_back(c.x);
            rows.y.push_back(c.y);
            rows.z.push_back(c.z);
            rows.azimuth.push_back(az);
            nearest[az] = -1;
        }
    }
    rows.row_begin.push_back(static_cast<int>(rows.x.size()));
}

}  // namespace stairmap
