#pragma once
// Plain point containers shared by every layer. The core knows no file formats or middleware.

#include <Eigen/Core>
#include <vector>

namespace stairmap {

/// A cloud of 3D points [m]. Which frame it is in is stated by whoever hands it over
/// (the detector expects the gravity-aligned robot frame: x forward, y left, z up).
using PointCloud = std::vector<Eigen::Vector3f>;

}  // namespace stairmap
