#pragma once
// Records the robot's climbs between floor levels for the landmark map (map/StaircaseTraversal.h):
// from the last position on level ground, through the samples taken while the level guard saw
// it climbing or descending, to the first position back on level ground.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "map/LandmarkTypes.h"

namespace stairmap::pipeline {

class TransitRecorder {
public:
    /// min_height_change_m: a climb that ends less than this above/below its start is dropped
    /// (a ramp or a bump, not another floor). sample_spacing_m: climb samples closer than this to
    /// the previous one are skipped. max_samples: longer climbs are thinned out (memory bound).
    explicit TransitRecorder(double min_height_change_m, double sample_spacing_m = 0.1,
                             std::size_t max_samples = 200);

    /// Feed the floor position under the robot (robot position minus its height) of every scan,
    /// with the level guard's verdict. Returns the finished transit when the robot regains level
    /// ground at another height.
    std::optional<FloorTransit> update(const Eigen::Vector3d& floor_position, bool level,
                                       double stamp_s);

private:
    void addClimbSample(const Eigen::Vector3d& floor_position);

    double min_height_change_m_;
    double sample_spacing_m_;
    std::size_t max_samples_;
    std::optional<Eigen::Vector3d> last_level_;
    std::vector<Eigen::Vector3d> path_;  ///< the climb under way (empty on level ground)
};

}  // namespace stairmap::pipeline
