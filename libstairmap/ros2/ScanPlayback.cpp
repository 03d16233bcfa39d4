#include "ros2/ScanPlayback.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace stairmap::ros2 {

PlaybackResult playScans(ScanSource& source, Ros2ScanPublisher& publisher, const PlaybackOptions& options,
                         const std::function<bool()>& stop) {
    if (!(options.rate > 0.0)) throw std::invalid_argument("rate: must be > 0");
    using Clock = std::chrono::steady_clock;
    const Eigen::Isometry3f T_sensor_robot = options.T_robot_sensor.inverse().cast<float>();
    PlaybackResult result;
    Clock::time_point start;
    while (!stop()) {
        std::optional<Scan> scan = source.next();
        if (!scan) break;
        if (result.scans == 0) {
            start = Clock::now();
            result.first_stamp_s = scan->stamp_s;
        }
        const auto due = start + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>((scan->stamp_s - result.first_stamp_s) / options.rate));
        // sleep in short steps so a stop request is seen promptly
        while (!stop() && Clock::now() < due)
            std::this_thread::sleep_for(std::min<Clock::duration>(due - Clock::now(), std::chrono::milliseconds(50)));
        if (stop()) break;
        PointCloud points_sensor;
        points_sensor.reserve(scan->points_robot.size());
        for (const Eigen::Vector3f& p : scan->points_robot) points_sensor.push_back(T_sensor_robot * p);
        result.last_stamp_s = scan->stamp_s;
        scan->stamp_s += options.stamp_offset_s;
        publisher.publish(*scan, points_sensor);
        ++result.scans;
        result.points += points_sensor.size();
    }
    return result;
}

}  // namespace stairmap::ros2
