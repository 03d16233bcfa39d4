#include "core/RowLinesCache.h"

#include <algorithm>

namespace stairmap {
namespace {

/// Same segmentation but for the point count.
bool sameButPoints(const SegmentationParams& a, const SegmentationParams& b) {
    return a.split_distance_m == b.split_distance_m && a.min_line_length_m == b.min_line_length_m &&
           a.max_point_gap_m == b.max_point_gap_m && a.point_sigma_m == b.point_sigma_m &&
           a.merge_chi2 == b.merge_chi2;
}

void appendWithPoints(const std::vector<LineSegment>& lines, int min_points,
                      std::vector<LineSegment>& out) {
    for (const LineSegment& l : lines)
        if (l.num_points >= min_points) out.push_back(l);
}

}  // namespace

void RowLinesCache::lines(const CylindricalRows& rows, const SegmentationParams& params,
                          int fewest_points, std::vector<LineSegment>& out) {
    for (std::size_t i = 0; i < used_; ++i) {
        const Entry& e = entries_[i];
        if (e.rows == &rows && sameButPoints(e.params, params) &&
            e.params.min_line_points <= params.min_line_points) {
            appendWithPoints(e.lines, params.min_line_points, out);
            return;
        }
    }
    if (used_ == entries_.size()) entries_.emplace_back();
    Entry& e = entries_[used_++];
    e.rows = &rows;
    e.params = params;
    e.params.min_line_points = std::min(fewest_points, params.min_line_points);
    e.lines.clear();
    segmentRows(rows, e.params, e.lines);
    appendWithPoints(e.lines, params.min_line_points, out);
}

}  // namespace stairmap
