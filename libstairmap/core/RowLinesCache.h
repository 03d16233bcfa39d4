#pragma once
// The lines of segmentRows shared between the detector's passes. The sparse-line pass
// (DetectorParams::sparse_line_points) segments the same rows as the first pass, asking for lines
// of fewer points; segmenting them twice cost half of that pass. The point count only filters:
// a chain or merged range with fewer points never changes how the others are split or merged, so
// the lines of N points or more are exactly segmentRows's with min_line_points N. The rows are
// segmented once for the fewest points any pass will ask, and each request takes those lines
// with at least its min_line_points, in segmentRows's order.

#include <cstddef>
#include <deque>
#include <vector>

#include "core/CylindricalRows.h"
#include "core/LineSegment.h"
#include "core/RowSegmentation.h"

namespace stairmap {

class RowLinesCache {
  public:
    /// Appends to `out` segmentRows(rows, params)'s lines. `fewest_points` (at most
    /// params.min_line_points): the rows are segmented once for lines of this many points, so
    /// later requests for fewer points (down to it) reuse the segmentation. `rows` must stay
    /// valid and unchanged until clear().
    void lines(const CylindricalRows& rows, const SegmentationParams& params, int fewest_points,
               std::vector<LineSegment>& out);
    /// Forgets every segmentation (call when the rows are rebuilt).
    void clear() { used_ = 0; }

  private:
    struct Entry {
        const CylindricalRows* rows = nullptr;
        SegmentationParams params;  ///< min_line_points: the fewest the lines were segmented for
        std::vector<LineSegment> lines;
    };
    std::deque<Entry> entries_;  ///< re-used between clear()s (no reallocation per cloud)
    std::size_t used_ = 0;
};

}  // namespace stairmap
