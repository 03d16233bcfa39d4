#include "pipeline/Scheduler.h"

#include <cmath>
#include <stdexcept>

namespace stairmap::pipeline {

Scheduler::Scheduler(const SchedulingParams& params) : params_(params) {
    if (!std::isfinite(params_.distance_m)) {
        throw std::invalid_argument("SchedulingParams.distance_m must be finite");
    }
    if (!std::isfinite(params_.angle_deg)) {
        throw std::invalid_argument("SchedulingParams.angle_deg must be finite");
    }
    if (!std::isfinite(params_.period_s)) {
        throw std::invalid_argument("SchedulingParams.period_s must be finite");
    }
}

bool Scheduler::update(double stamp_s, const Eigen::Isometry3d& T_world_robot) {
    const Eigen::Vector3d position = T_world_robot.translation();
    if (last_position_) travelled_m_ += (position - *last_position_).norm();
    last_position_ = position;
    if (!due(stamp_s, T_world_robot)) return false;
    last_run_ = State{stamp_s, T_world_robot};
    travelled_m_ = 0.0;
    return true;
}

bool Scheduler::due(double stamp_s, const Eigen::Isometry3d& T_world_robot) const {
    if (!last_run_) return true;
    if (params_.distance_m > 0 && travelled_m_ >= params_.distance_m) return true;
    if (params_.period_s > 0 && stamp_s - last_run_->stamp_s >= params_.period_s) return true;
    if (params_.angle_deg > 0) {
        const Eigen::Matrix3d R_last_now =
            last_run_->T_world_robot.linear().transpose() * T_world_robot.linear();
        const double angle_deg = Eigen::AngleAxisd(R_last_now).angle() * 180.0 / M_PI;
        if (angle_deg >= params_.angle_deg) return true;
    }
    return false;
}

}  // namespace stairmap::pipeline
