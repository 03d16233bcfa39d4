#pragma once
// Publishes scans as ROS 2 sensor_msgs/PointCloud2 (in the sensor frame) and nav_msgs/Odometry
// (the robot pose in the world frame), reliable, volatile: `stairmap play --ros2`, the demo and
// test source of `stairmap live --ros2`. The odometry of a scan is written before its cloud so
// that a subscriber has the pose when the cloud arrives.

#include <functional>
#include <string>

#include "core/Scan.h"
#include "ros2/DdsSupport.h"
#include "ros2/Ros2Options.h"

namespace stairmap::ros2 {

class Ros2ScanPublisher {
public:
    /// Throws std::invalid_argument for a bad topic name, std::runtime_error if DDS fails.
    explicit Ros2ScanPublisher(const Ros2PlayOptions& options);

    /// Writes the odometry (scan.T_world_robot at scan.stamp_s) and the cloud
    /// `points_sensor` (the scan's points in the sensor frame) with the same stamp.
    void publish(const Scan& scan, const PointCloud& points_sensor);
    /// Waits until the clouds have at least one subscriber or timeout_s passed or stop() is true,
    /// then up to 1 s more (within timeout_s) until the odometry has one too, so that the first
    /// scans do not reach a subscriber without their poses; returns the cloud subscribers matched.
    int waitForSubscribers(double timeout_s, const std::function<bool()>& stop) const;
    /// Waits up to timeout_s for reliable subscribers to acknowledge everything written.
    void flush(double timeout_s) const;

private:
    Ros2PlayOptions options_;
    std::string points_dds_, odom_dds_;
    DdsEntity participant_;
    dds_entity_t points_writer_ = 0, odom_writer_ = 0;
};

}  // namespace stairmap::ros2
