#pragma once
// TUM trajectories ("timestamp tx ty tz qx qy qz qw" per line, '#' comments): the usual output of
// SLAM systems such as MOLA. Used as the preferred source of robot poses for a rawlog replay.

#include <Eigen/Geometry>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace stairmap::io {

/// One timestamped robot pose.
struct TimedPose {
    double stamp_s = 0.0;  ///< [s]
    Eigen::Isometry3d T_world_robot = Eigen::Isometry3d::Identity();
};

/// A time-ordered trajectory with interpolation. Memory: 128 B per pose.
class TumTrajectory {
public:
    /// Reads a TUM file. Throws std::runtime_error "<path>:<line>: <problem>" for a missing file,
    /// a line without 8 numbers, non-finite values, a zero quaternion or non-increasing time.
    static TumTrajectory load(const std::string& path);
    /// Same, from a stream; `name` is used in error messages.
    static TumTrajectory read(std::istream& in, const std::string& name);

    /// Writes "t x y z qx qy qz qw" lines (full double precision). save() throws naming the file.
    void write(std::ostream& out) const;
    void save(const std::string& path) const;

    /// Appends a pose; throws std::invalid_argument unless stamp_s is later than the last one.
    void append(double stamp_s, const Eigen::Isometry3d& T_world_robot);

    /// Pose at time t: linear interpolation of the position, slerp of the orientation between
    /// the two neighbouring poses. Within `tolerance_s` outside the time span the end pose is
    /// returned; farther out, std::nullopt. Cost: O(log n).
    std::optional<Eigen::Isometry3d> poseAt(double t, double tolerance_s = 0.0) const;

    const std::vector<TimedPose>& poses() const { return poses_; }
    bool empty() const { return poses_.empty(); }
    std::size_t size() const { return poses_.size(); }

private:
    std::vector<TimedPose> poses_;
};

}  // namespace stairmap::io
