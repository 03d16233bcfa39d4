#pragma once
// One 3D cloud from an MRPT rawlog (what `stairmap detect` reads from a .rawlog file).

#include <string>

#include "core/PointCloud.h"

namespace stairmap::io {

/// Reads the first 3D observation of an MRPT rawlog (plain or gzipped, format #1 or #2) and returns
/// its points in the robot frame. Throws std::runtime_error("<path>: <problem>").
PointCloud readRawlogCloud(const std::string& path);

}  // namespace stairmap::io
