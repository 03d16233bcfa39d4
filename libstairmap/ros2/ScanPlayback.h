#pragma once
// Replays a scan source on ROS 2 at its recorded rate x R (`stairmap play --ros2`).

#include <Eigen/Geometry>
#include <functional>
#include <cstddef>

#include "core/Scan.h"
#include "ros2/Ros2ScanPublisher.h"

namespace stairmap::ros2 {

struct PlaybackOptions {
    double rate = 1.0;  ///< [-] speed factor on the recorded stamps (2: twice as fast); > 0
    /// T_robot_sensor: the clouds are published in this sensor frame (points_sensor =
    /// T_robot_sensor^-1 * points_robot), so a subscriber with the same [sensor] pose_* gets the
    /// robot-frame points back.
    Eigen::Isometry3d T_robot_sensor = Eigen::Isometry3d::Identity();
    double stamp_offset_s = 0.0;  ///< [s] added to every stamp (later loops keep stamps increasing)
};

struct PlaybackResult {
    std::size_t scans = 0;
    std::size_t points = 0;
    double first_stamp_s = 0.0, last_stamp_s = 0.0;  ///< [s] as recorded (without the offset)
};

/// Publishes every scan of `source`, sleeping so that scan k goes out (t_k - t_0) / rate after
/// the first. Returns early when `stop()` returns true. Throws what the source or the publisher throw.
PlaybackResult playScans(ScanSource& source, Ros2ScanPublisher& publisher, const PlaybackOptions& options,
                         const std::function<bool()>& stop);

}  // namespace stairmap::ros2
