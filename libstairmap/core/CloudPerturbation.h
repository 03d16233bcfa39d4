#pragma once
// Another realisation of a cloud, for evaluation: every coordinate moved by its own uniform offset
// in [-amplitude, +amplitude]. At 0.01 mm, against a sensor's 1 cm of range noise, it changes
// nothing physical; but it breaks the exact ties of a cloud written on a lattice (the random
// benchmark's coordinates are multiples of 1/512 m) and re-draws every decision that sits on a
// threshold. How far the scores move over such realisations is the evaluation's noise floor, and a
// score that holds only on one realisation was fitted to it (docs/detector.md, session of
// 2026-12-07, eighth).

#include <cstdint>
#include <string>

#include "core/PointCloud.h"

namespace stairmap {

/// [m] largest amplitude accepted: a realisation, not a change of the scene (sensor noise is ~1 cm)
constexpr double kMaxPerturbationM = 0.01;

/// Moves every coordinate of `cloud` by an offset drawn uniformly in [-amplitude_m, amplitude_m].
/// The offsets depend only on (seed, stream, point index): the same cloud gets the same
/// realisation in every run and on every machine. Non-finite coordinates stay non-finite;
/// amplitude_m = 0 leaves the cloud unchanged. Throws std::invalid_argument unless
/// 0 <= amplitude_m <= kMaxPerturbationM.
void perturbCloud(PointCloud& cloud, double amplitude_m, std::uint64_t seed, std::uint64_t stream);

/// A stream number for perturbCloud from a name (a cloud's file name): FNV-1a, the same on every
/// platform, so each cloud of a set gets its own offsets.
std::uint64_t perturbationStream(const std::string& name);

}  // namespace stairmap
