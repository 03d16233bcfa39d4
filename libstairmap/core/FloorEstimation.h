#pragma once
// Height of the floor the robot stands on: the dominant horizontal level of the points near it.

#include <optional>

#include "core/PointCloud.h"

namespace stairmap {

struct FloorSearch {
    double z_lo = -3.0;       ///< [m] lowest candidate level
    double z_hi = 0.3;        ///< [m] highest candidate level
    double radius_m = 3.0;    ///< [m] only points within this XY radius vote
    double bin_m = 0.02;      ///< [m] histogram bin
    int min_support = 30;     ///< [-] fewest points on the winning level
};

/// Mode of the z histogram (3-bin window) of the points within radius_m, refined to the mean z of
/// the points within one bin of the mode. std::nullopt if the best level has too little support.
/// Non-finite points are skipped. Cost: one pass over (at most ~10k points of) the cloud.
std::optional<double> dominantLevel(const PointCloud& cloud, const FloorSearch& search);

}  // namespace stairmap
