#include "core/StairDetector.h"

namespace stairmap {

StairDetector::StairDetector(const DetectorParams& params) : params_(params) {
    params_.validate();
}

// TODO(detector): pipeline being written (preprocessing, segmentation, Algorithm 1).
DetectionResult StairDetector::detect(const PointCloud& /*cloud_robot*/,
                                      std::optional<double> floor_z) const {
    DetectionResult result;
    result.floor_z = floor_z.value_or(0.0);
    result.floor_estimated = !floor_z.has_value();
    return result;
}

}  // namespace stairmap
