#include "core/CylindricalRows.h"

#include <algorithm>
#include <cmath>

namespace stairmap {

void buildCylindricalRows(const std::vector<TopViewCell>& cells, std::uint8_t flag,
                          const CylindricalParams& p, CylindricalRows& rows) {
    rows.x.clear();
    rows.y.clear();
    rows.z.clear();
    rows.azimuth.clear();
    rows.row_begin.clear();
    rows.azimuth_bins = p.azimuth_bins;
    const int nrows = static_cast<int>(std::ceil((p.z_hi - p.z_lo) / p.row_height_m));
    const double az_scale = p.azimuth_bins / (2 * M_PI);
    // key = (row * bins + azimuth) << 32 | range in 0.1 mm, index kept alongside.
    std::vector<std::pair<std::uint64_t, int>> keyed;
    keyed.reserve(cells.size() / 4 + 16);
    for (int i = 0; i < static_cast<int>(cells.size()); ++i) {
        const TopViewCell& c = cells[i];
        if (!(c.flags & flag)) continue;
        // Row r spans [r - 0.5, r + 1.5) row heights: overlapping windows, so that an edge whose
        // points straddle a row boundary (noise) lies whole in at least one row.
        const double fr = (c.z - p.z_lo) / p.row_height_m;
        const int row = static_cast<int>(std::floor(fr));
        const int other = (fr - row < 0.5) ? row - 1 : row + 1;
        int az = static_cast<int>((std::atan2(c.y, c.x) + M_PI) * az_scale);
        az = std::clamp(az, 0, p.azimuth_bins - 1);
        const double range = std::sqrt(double(c.x) * c.x + double(c.y) * c.y);
        const auto range_q = static_cast<std::uint64_t>(std::min(range * 1e4, 4.0e9));
        for (int r : {row, other}) {
            if (r < 0 || r >= nrows) continue;
            const std::uint64_t cell_key = static_cast<std::uint64_t>(r) * p.azimuth_bins + az;
            keyed.emplace_back((cell_key << 32) | range_q, i);
        }
    }
    std::sort(keyed.begin(), keyed.end());
    std::uint64_t last_cell = ~std::uint64_t(0);
    int last_row = -1;
    for (const auto& [key, idx] : keyed) {
        const std::uint64_t cell_key = key >> 32;
        if (cell_key == last_cell) continue;  // a nearer point already holds this cell
        last_cell = cell_key;
        const int row = static_cast<int>(cell_key / p.azimuth_bins);
        if (row != last_row) {
            rows.row_begin.push_back(static_cast<int>(rows.x.size()));
            last_row = row;
        }
        rows.x.push_back(cells[idx].x);
        rows.y.push_back(cells[idx].y);
        rows.z.push_back(cells[idx].z);
        rows.azimuth.push_back(static_cast<int>(cell_key % p.azimuth_bins));
    }
    rows.row_begin.push_back(static_cast<int>(rows.x.size()));
}

}  // namespace stairmap
