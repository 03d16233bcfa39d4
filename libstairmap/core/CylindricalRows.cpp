#include "core/CylindricalRows.h"

#include <algorithm>
#include <cmath>

#include "core/AzimuthBin.h"

namespace stairmap {

namespace {

/// One candidate entry of a row: azimuth bin, range and cell index.
struct Entry {
    int row, az;
    float range;
    int cell;
};

/// Stable counting sort of `in` by key(e) in [0, nkeys) into `out`; `start` receives the offset of
/// each key's run (+ end). O(n + nkeys).
template <typename Key>
void countingSort(const std::vector<Entry>& in, int nkeys, Key key, std::vector<Entry>& out,
                  std::vector<int>& start) {
    start.assign(nkeys + 1, 0);
    for (const Entry& e : in) ++start[key(e) + 1];
    for (int k = 0; k < nkeys; ++k) start[k + 1] += start[k];
    thread_local std::vector<int> tl_fill;
    std::vector<int>& fill = tl_fill;
    fill.assign(start.begin(), start.end() - 1);
    out.resize(in.size());
    for (const Entry& e : in) out[fill[key(e)]++] = e;
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
    const AzimuthBinner azimuth_bin(p.azimuth_bins);
    const float inv_row = static_cast<float>(1.0 / p.row_height_m);
    const float skip_lo = static_cast<float>(p.skip_z_lo), skip_hi = static_cast<float>(p.skip_z_hi);
    // Per-thread scratch, re-used between calls (no page faults on fresh memory).
    thread_local std::vector<Entry> tl_entries, tl_by_azimuth, tl_sorted;
    thread_local std::vector<int> tl_row_start;
    std::vector<Entry>& entries = tl_entries;
    std::vector<Entry>& by_azimuth = tl_by_azimuth;
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
        const int az = azimuth_bin(c.x, c.y);
        const float range = std::sqrt(c.x * c.x + c.y * c.y);
        for (int r : {row, other}) {
            if (r >= 0 && r < nrows) entries.push_back({r, az, range, i});
        }
    }
    // Sorted by azimuth, then (stably) by row: each row comes out in azimuth order, and the entries
    // of one cell of the array are consecutive, in candidate order.
    countingSort(entries, p.azimuth_bins, [](const Entry& e) { return e.az; }, by_azimuth, row_start);
    countingSort(by_azimuth, nrows, [](const Entry& e) { return e.row; }, sorted, row_start);
    for (int r = 0; r < nrows; ++r) {
        if (row_start[r] == row_start[r + 1]) continue;
        rows.row_begin.push_back(static_cast<int>(rows.x.size()));
        for (int k = row_start[r]; k < row_start[r + 1];) {
            int best = k;  // the nearest entry of this cell; the first one on a tie
            int end = k + 1;
            for (; end < row_start[r + 1] && sorted[end].az == sorted[k].az; ++end) {
                if (sorted[end].range < sorted[best].range) best = end;
            }
            const TopViewCell& c = cells[sorted[best].cell];
            rows.x.push_back(c.x);
            rows.y.push_back(c.y);
            rows.z.push_back(c.z);
            rows.azimuth.push_back(sorted[k].az);
            k = end;
        }
    }
    rows.row_begin.push_back(static_cast<int>(rows.x.size()));
}

namespace {
bool sameParams(const CylindricalParams& a, const CylindricalParams& b) {
    return a.z_lo == b.z_lo && a.z_hi == b.z_hi && a.row_height_m == b.row_height_m &&
           a.azimuth_bins == b.azimuth_bins && a.skip_z_lo == b.skip_z_lo &&
           a.skip_z_hi == b.skip_z_hi;
}
}  // namespace

const CylindricalRows& CylindricalRowsCache::rows(const std::vector<TopViewCell>& cells,
                                                  std::uint8_t flag,
                                                  const CylindricalParams& params) {
    for (std::size_t i = 0; i < used_; ++i)
        if (entries_[i].flag == flag && sameParams(entries_[i].params, params))
            return entries_[i].rows;
    if (used_ == entries_.size()) entries_.emplace_back();
    Entry& e = entries_[used_++];
    e.flag = flag;
    e.params = params;
    buildCylindricalRows(cells, flag, params, e.rows);
    return e.rows;
}

}  // namespace stairmap
