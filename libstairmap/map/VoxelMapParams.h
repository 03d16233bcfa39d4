#pragma once
// Parameters of the voxel map ([map] section). Header only, so io/ can load them without map/.

namespace stairmap::map {

enum class VoxelInsertionMode { Endpoints, RayCast };

/// [map] section of the config.
struct VoxelMapParams {
    double resolution_m = 0.05;  ///< [m] leaf voxel edge length (> 0)
    VoxelInsertionMode insertion_mode = VoxelInsertionMode::Endpoints;
    double max_range_m = 20.0;   ///< [m] points farther than this from the sensor origin are not
                                 ///< inserted (<= 0: no limit)
    int insert_every_n_scans = 1;  ///< [-] the mapper inserts every n-th scan only (>= 1; speed)
};

}  // namespace stairmap::map
