#pragma once
// Pre-processing, paper Sec. III-A, second step: organise the top-view columns into a cylindrical
// array around the robot (rows = z bins, columns = azimuth bins over [-180, 180) deg) keeping the
// point nearest to the robot per cell. Only nosing candidates (a TopViewFlag) enter, so a cell's
// nearest point is a point of the nearest edge, not of the surface behind it.

#include <cstdint>
#include <deque>
#include <vector>

#include "core/TopView.h"

namespace stairmap {

struct CylindricalParams {
    double z_lo = -3.0;        ///< [m] bottom of row 0
    double z_hi = 3.0;         ///< [m] top of the last row
    double row_height_m = 0.025;  ///< [m]
    int azimuth_bins = 1800;   ///< [-] over 360 deg
    /// [m] cells with z inside (skip_z_lo, skip_z_hi) are left out: the ground band, whose lines
    /// Algorithm 1 never uses (a sparse floor would flood the rows with candidates).
    double skip_z_lo = 0.0;
    double skip_z_hi = 0.0;
};

/// Rows of the array, each in azimuth order; points stored as structure of arrays.
struct CylindricalRows {
    std::vector<float> x, y, z;    ///< [m] kept points, grouped by row, ascending azimuth within a row
    std::vector<int> azimuth;      ///< azimuth bin of each kept point
    std::vector<int> row_begin;    ///< offsets of the non-empty rows into the point arrays (+ end)
    int azimuth_bins = 0;
};

/// Fills `rows` from the cells having `flag`. Cost O(m log m) worst case, O(m) typically, for m selected cells
/// (counting sort by row, flat nearest-per-bin array per row).
void buildCylindricalRows(const std::vector<TopViewCell>& cells, std::uint8_t flag,
                          const CylindricalParams& params, CylindricalRows& rows);

/// Arrays built from one set of cells, kept per (flag, params): a detector's later passes (taller
/// rows, longer gaps) ask again for the arrays its first passes built. Valid while the cells are
/// unchanged: clear() when they change (the arrays' memory is kept for the next ones).
class CylindricalRowsCache {
public:
    /// The array of `cells` for (flag, params), built on first request; the reference stays valid
    /// until clear() (entries live in a deque: later requests never move them).
    const CylindricalRows& rows(const std::vector<TopViewCell>& cells, std::uint8_t flag,
                                const CylindricalParams& params);
    void clear() { used_ = 0; }

private:
    struct Entry {
        std::uint8_t flag = 0;
        CylindricalParams params;
        CylindricalRows rows;
    };
    std::deque<Entry> entries_;
    std::size_t used_ = 0;
};

}  // namespace stairmap
