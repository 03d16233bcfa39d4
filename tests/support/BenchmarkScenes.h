#pragma once
// Scenes of the randomised benchmark rebuilt in-process exactly as `stairmap sim --random` writes
// them, and a loose test of whether a detection reports one of their flights (test side only).

#include "core/Staircase.h"
#include "sim/RandomCloud.h"

namespace stairmap::test {

/// Scene `index` of the randomised set `seed` as `stairmap sim --random` writes it (coordinates in
/// 2^-9 m steps, points sorted), so the cloud is the one `make eval` scores.
sim::RandomCloud benchmarkScene(int seed, int index);

/// Is `s` a report of the flight `truth`: half of its edges or more within 0.3 m of a true nosing
/// of about their height (a second chain through the same flight's scattered nosings counts too)?
bool reportsFlight(const Staircase& s, const StaircaseTruth& truth);

}  // namespace stairmap::test
