#pragma once
// The robot's recent poses from odometry messages, interpolated at a cloud's stamp. ROS 2 has no
// shared clock between a cloud and the odometry, so a cloud is placed between the two odometry
// poses around its stamp (linear position, slerp orientation), never extrapolated far.

#include <Eigen/Geometry>
#include <cstddef>
#include <deque>

namespace stairmap::ros2 {

struct PoseBufferParams {
    double max_gap_s = 1.0;      ///< [s] two poses farther apart than this are not interpolated
    double tolerance_s = 0.02;   ///< [s] a stamp this close beyond the newest/oldest pose uses it
    double keep_s = 30.0;        ///< [s] poses older than newest - keep_s are forgotten
    std::size_t max_poses = 4096;  ///< [-] hard bound on the memory
};

enum class PoseLookup {
    Found,     ///< pose is set
    NotYet,    ///< no pose at or after the stamp yet: wait for more odometry
    TooOld,    ///< the stamp is before the oldest pose kept
    Gap,       ///< the poses around the stamp are more than max_gap_s apart
};

class PoseBuffer {
public:
    explicit PoseBuffer(const PoseBufferParams& params = {}) : params_(params) {}

    /// Adds a pose. Out-of-order or duplicate stamps (older than the newest) are ignored and
    /// return false; so are non-finite ones.
    bool add(double stamp_s, const Eigen::Isometry3d& T_world_robot);
    /// T_world_robot at `stamp_s`.
    PoseLookup lookup(double stamp_s, Eigen::Isometry3d& T_world_robot) const;

    std::size_t size() const { return poses_.size(); }
    double newestStamp() const { return poses_.empty() ? -1e300 : poses_.back().stamp_s; }

private:
    struct Stamped {
        double stamp_s;
        Eigen::Vector3d t;
        Eigen::Quaterniond q;
    };
    PoseBufferParams params_;
    std::deque<Stamped> poses_;
};

}  // namespace stairmap::ros2
