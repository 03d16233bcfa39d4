#pragma once
// Human-readable reasons for the stair rules (Definition 1 and the chain length), used only to fill
// a DetectorDebug record. explainStairPair() applies the very thresholds of checkStairPair() and
// says which one failed first; tests hold the two to the same verdict.

#include <string>
#include <vector>

#include "core/DetectorDebug.h"
#include "core/DetectorParams.h"
#include "core/LineSegment.h"

namespace stairmap {

/// "" if checkStairPair(lower, upper, p) accepts the pair, else the failed rule with the measured
/// value and the limit, e.g. "rise 0.34 > 0.30 m", "not parallel: 14°", "run 0.52 > 0.45 m".
std::string explainStairPair(const LineSegment& lower, const LineSegment& upper,
                             const DetectorParams& p);

/// "2 steps < 4": the chain-length rule.
std::string tooFewSteps(std::size_t steps, int min_steps);

/// Appends to `out` (up to DetectorDebug::kMaxRejected in all) the pairs of `sorted_lines` (z
/// upwards from the floor, mirrored for descending) that look like consecutive steps but were
/// refused, each with its reason. A pair is looked at when neither line is in `used` and the upper
/// line is the nearest one above the lower within two rises and two runs. For descending lines the
/// stored edges are mirrored back about `floor_z` (real z). Cost: O(lines^2) at worst; debug only.
void explainRefusedPairs(const std::vector<LineSegment>& sorted_lines,
                         const std::vector<char>& used, StairDirection direction,
                         double floor_z, const DetectorParams& p,
                         std::vector<RejectedChain>& out);

}  // namespace stairmap
