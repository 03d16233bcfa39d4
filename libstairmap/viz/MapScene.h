#pragma once
// The map as an MRPT 3D scene (.3Dscene, opens in SceneViewer3D): voxel centres as a point cloud
// coloured by height, the trajectory as lines, each staircase landmark as step boxes with its ID.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "map/LandmarkTypes.h"
#include "map/VoxelMap.h"

namespace stairmap::viz {

/// What a map picture shows (all world frame).
struct MapView {
    const map::VoxelMap* voxels = nullptr;                         ///< may be null (no voxels drawn)
    std::vector<StaircaseLandmark> staircases;
    std::vector<Floor> floors;                                ///< reported floors, by height
    std::vector<Eigen::Vector3d> trajectory;                  ///< [m] robot positions in order
};

/// Writes the scene gzip-compressed to `path`. Throws std::runtime_error naming the path.
/// Cost: O(voxels); no display needed.
void saveMapScene(const MapView& view, const std::string& path);

}  // namespace stairmap::viz
