#pragma once
// Helpers comparing detections with the synthetic ground truth (test side only).

#include <string>

#include "support/SyntheticScenes.h"
#include "core/StairDetector.h"

namespace stairmap::test {

/// The detected staircase of the truth's direction whose first edge lies on the true first nosing
/// (XY distance of its centre to the true nosing line < 0.08 m, |dz| < 0.05 m), or nullptr.
const Staircase* matchTruth(const DetectionResult& result, const StairTruth& truth);

/// Largest distance from a detected edge centre to the nearest true nosing segment [m].
double nosingError(const Staircase& s, const StairTruth& truth);

/// Absolute heading difference [rad].
double headingError(const Staircase& s, const StairTruth& truth);

/// One line per staircase, for failure messages.
std::string describe(const DetectionResult& result);

}  // namespace stairmap::test
