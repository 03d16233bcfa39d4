#pragma once
// Conversions between MRPT poses and Eigen isometries, kept in io/ so the core never sees MRPT.

#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>

namespace stairmap::io {

/// The rigid transform an MRPT pose describes (maps child-frame coordinates to the parent frame).
Eigen::Isometry3d toIsometry(const mrpt::poses::CPose3D& pose);

/// The MRPT pose of a rigid transform (rotation is re-orthonormalised by MRPT as needed).
mrpt::poses::CPose3D toCPose3D(const Eigen::Isometry3d& T);

}  // namespace stairmap::io
