#pragma once
// The detector's intermediate results for one call of StairDetector::detect, for viewers and for
// "why was this flight missed?" questions. Filled only when the caller passes a record: without
// one the detector does no extra work (see bench_detector's *_Debug variants for the cost with).
// Everything is in the frame of the input cloud (the gravity-aligned robot frame) with real z.

#include <string>
#include <vector>

#include "core/LineSegment.h"
#include "core/Staircase.h"
#include "core/TopView.h"

namespace stairmap {

/// A candidate chain of edges that did not become a staircase, with the rule that stopped it.
struct RejectedChain {
    StairDirection direction = StairDirection::Ascending;
    std::vector<LineSegment> edges;  ///< from the floor outward (often a single pair)
    std::string reason;              ///< e.g. "rise 0.34 > 0.30 m", "not parallel: 14°", "2 steps < 4"
};

struct DetectorDebug {
    double floor_z = 0.0;                    ///< [m] floor height used
    double floor_noise_m = 0.0;              ///< [m] floor height noise measured (0: not measured)
    double split_distance_m = 0.0;           ///< [m] d_p used (raised for a noisy cloud)
    std::vector<TopViewCell> candidates;     ///< top-view nosing candidate columns (flags set)
    std::vector<LineSegment> lines_ascending;   ///< lines of the front-drop rows (one row each)
    std::vector<LineSegment> lines_descending;  ///< lines of the back-drop rows
    std::vector<Staircase> accepted;         ///< the flights returned (same as the result)
    std::vector<RejectedChain> rejected;     ///< at most kMaxRejected, nearest pairs first found

    static constexpr std::size_t kMaxRejected = 64;

    void clear() { *this = DetectorDebug{}; }
};

}  // namespace stairmap
