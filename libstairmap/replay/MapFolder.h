#pragma once
// A finished `stairmap map` output folder, loaded for browsing: landmarks.json (required),
// map.bt (optional: voxels) and the trajectory of the robot poses in detections.jsonl (optional).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "map/LandmarkMap.h"
#include "map/VoxelMap.h"

namespace stairmap::replay {

struct MapFolder {
    std::string path;
    LandmarkMap landmarks;
    std::optional<map::VoxelMap> voxels;          ///< from map.bt when present
    std::vector<Eigen::Vector3d> trajectory;      ///< [m] robot positions at the detections
    std::optional<Eigen::Isometry3d> last_pose;   ///< the robot at the last detection
};

/// True if `dir` is a directory holding landmarks.json.
bool isMapFolder(const std::string& dir);

/// Throws std::runtime_error naming the file and the problem.
MapFolder loadMapFolder(const std::string& dir);

}  // namespace stairmap::replay
