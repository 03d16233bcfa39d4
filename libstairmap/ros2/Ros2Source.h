#pragma once
// A live scan source on ROS 2 topics (issue 11, `stairmap live --ros2`): sensor_msgs/PointCloud2
// clouds in the sensor frame and nav_msgs/Odometry poses, both read best-effort (so they accept
// best-effort and reliable publishers). Each cloud is decoded at once (ros2/PointCloudDecoder.h),
// then waits (bounded, pose_wait_s) for odometry at or after its stamp, is placed at the pose
// interpolated to its stamp, moved into the robot frame (T_robot_sensor) and pushed to the sink.
// Lossy: the runner drops the oldest scans when it falls behind.
//
// Counters: clouds_received, scans_pushed, clouds_without_xyz, malformed_clouds,
// clouds_without_pose (odometry never came, came with a gap or too late), odometry_received,
// malformed_odometry (non-finite or zero quaternion), odometry_out_of_order, non_finite_points.

#include <atomic>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "live/LiveSource.h"
#include "ros2/DdsSupport.h"
#include "ros2/PoseBuffer.h"
#include "ros2/Ros2Options.h"

namespace stairmap::ros2 {

class Ros2Source : public live::LiveSource {
public:
    /// Validates the topic names (throws std::invalid_argument naming the topic); DDS entities
    /// are made in run().
    explicit Ros2Source(const Ros2SourceOptions& options);

    /// Runs until `stop`; throws std::runtime_error if DDS cannot be set up.
    void run(live::ScanSink& sink, const std::atomic<bool>& stop) override;
    bool lossy() const override { return true; }
    std::string describe() const override;
    std::map<std::string, std::size_t> counters() const override;

private:
    struct Waiting {
        double stamp_s;
        PointCloud points_sensor;
        double arrived_s;  ///< [s] monotonic clock
    };
    void takeOdometry(dds_entity_t reader);
    void takeClouds(dds_entity_t reader);
    void onCloud(const void* sample);
    void releaseWaiting(live::ScanSink& sink);
    void count(const std::string& name, std::size_t n = 1);

    Ros2SourceOptions options_;
    std::string points_dds_, odom_dds_;
    PoseBuffer poses_;
    std::deque<Waiting> waiting_;
    std::size_t next_index_ = 0;
    mutable std::mutex counters_mutex_;
    std::map<std::string, std::size_t> counters_;
};

/// The source as a LiveSource for the live runner (`stairmap live --ros2`).
std::unique_ptr<live::LiveSource> makeRos2Source(const Ros2SourceOptions& options);

}  // namespace stairmap::ros2
