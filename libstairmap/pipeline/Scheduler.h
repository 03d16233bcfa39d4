#pragma once
// Decides when the detector runs: every N metres travelled, M degrees turned or T seconds.

#include <Eigen/Geometry>
#include <optional>

#include "pipeline/MapperParams.h"

namespace stairmap::pipeline {

class Scheduler {
public:
    /// Throws std::invalid_argument naming the field if a parameter is not finite.
    explicit Scheduler(const SchedulingParams& params = {});

    /// Feed every scan's stamp and pose in order. Returns true when the detector should run now:
    /// on the first scan, then whenever the path length, the rotation angle or the time since the
    /// last run reaches its threshold. The counters restart at each run.
    bool update(double stamp_s, const Eigen::Isometry3d& T_world_robot);

private:
    struct State {
        double stamp_s;
        Eigen::Isometry3d T_world_robot;
    };
    bool due(double stamp_s, const Eigen::Isometry3d& T_world_robot) const;

    SchedulingParams params_;
    std::optional<State> last_run_;
    std::optional<Eigen::Vector3d> last_position_;
    double travelled_m_ = 0.0;
};

}  // namespace stairmap::pipeline
