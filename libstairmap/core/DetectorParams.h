#pragma once
// Detector parameters with the paper's defaults. Owner: detector engineer (placeholder to be filled).

namespace stairmap {

struct DetectorParams {
    double leaf_size_m = 0.025;  ///< [m] voxel grid leaf (paper Sec. IV-A)
};

}  // namespace stairmap
