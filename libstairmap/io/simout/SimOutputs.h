#pragma once
// Small text outputs of `stairmap sim`: TUM trajectories ("t x y z qx qy qz qw" per line).

#include <Eigen/Geometry>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace stairmap::io {

using StampedPoses = std::vector<std::pair<double, Eigen::Isometry3d>>;

/// Writes one "t x y z qx qy qz qw" line per pose (9 decimals for t and positions).
void writeTumPoses(std::ostream& out, const StampedPoses& poses);
/// File wrapper; throws std::runtime_error naming the path on failure.
void writeTumPosesFile(const std::string& path, const StampedPoses& poses);

}  // namespace stairmap::io
