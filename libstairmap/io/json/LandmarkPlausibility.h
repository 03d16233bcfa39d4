#pragma once
// Physical plausibility of a loaded landmark map (docs/landmarks.md, "Limits of a loaded map"):
// a schema-valid document can still hold numbers no building has (a coordinate of 1e12, a rise of
// 40 m, a negative variance) that would overflow or poison the map it is merged into. These bounds
// are also stated in docs/landmarks.schema.json.

#include <string>

#include "map/LandmarkTypes.h"

namespace stairmap::io {

constexpr double kWorldBoundXyM = 1e5;   ///< [m] |x|, |y| of any loaded point
constexpr double kWorldBoundZM = 1e4;    ///< [m] |z| of any loaded point
constexpr double kMaxStampS = 1e10;      ///< [s] |stamp| (Unix time in 2286)
constexpr double kMaxStepHeightM = 2.0;  ///< [m] rise (the detector's own upper bound)
constexpr double kMaxStepDepthM = 3.0;   ///< [m] run (the detector's own upper bound)
constexpr double kMaxStepWidthM = 100.0; ///< [m] edge length
constexpr double kMaxVariance = 1e4;     ///< [m^2, rad^2, m rad] entries of cov_rho_theta
constexpr int kMaxStepsPerStaircase = 1000;
constexpr int kMaxCount = 1000000000;    ///< observations, points, samples

/// Throws std::runtime_error("<JSON field path>: <value> <problem>") for the first implausible
/// value, e.g. "staircases[0].location[0]: 1e+12 is outside the world bound |x|, |y| <= 1e+05 m".
void checkLandmarkPlausibility(const LandmarkMapState& state);

/// Throws like checkLandmarkPlausibility unless |z| <= kWorldBoundZM (for values outside the state,
/// such as the reported floors).
void checkWorldZ(double z, const std::string& path);

}  // namespace stairmap::io
