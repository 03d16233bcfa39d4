#pragma once
// Public API of the staircase detector (paper Sec. III). Owner: detector engineer; this file fixes the
// contract other layers code against. Implementation in StairDetector.cpp.

#include <optional>
#include <vector>

#include "core/DetectorDebug.h"
#include "core/DetectorParams.h"
#include "core/PointCloud.h"
#include "core/Staircase.h"

namespace stairmap {

struct DetectionResult {
    std::vector<Staircase> staircases;  ///< ascending and descending, robot frame
    double floor_z = 0.0;               ///< [m] floor height that was used
    bool floor_estimated = false;       ///< true when floor_z was estimated from the cloud
};

/// Detects ascending and descending staircases all around the robot.
/// Input: a cloud in the gravity-aligned robot frame (x forward, y left, z up). Non-finite points are
/// ignored; an empty cloud gives an empty result. Cost: linear in the number of points.
class StairDetector {
public:
    /// Throws std::invalid_argument naming the field if a parameter is out of range.
    explicit StairDetector(const DetectorParams& params = {});

    /// floor_z: height of the floor the robot stands on [m] (= -robot height); estimated when absent.
    /// debug: when not null, cleared and filled with the intermediate results (costs extra time
    /// and memory); null (the default) adds no work. The result is the same either way.
    DetectionResult detect(const PointCloud& cloud_robot,
                           std::optional<double> floor_z = std::nullopt,
                           DetectorDebug* debug = nullptr) const;

    const DetectorParams& params() const { return params_; }

private:
    DetectorParams params_;
};

}  // namespace stairmap
