#include "ros2/Ros2ScanPublisher.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "ros2/MessageBuilders.h"

namespace stairmap::ros2 {

Ros2ScanPublisher::Ros2ScanPublisher(const Ros2PlayOptions& options)
    : options_(options),
      points_dds_(ddsTopicName(options.points_topic)),
      odom_dds_(ddsTopicName(options.odom_topic)) {
    participant_ = createParticipant();
    const dds_entity_t p = participant_.get();
    points_writer_ = createWriter(p, createTopic(p, &sensor_msgs_msg_dds__PointCloud2__desc, points_dds_),
                                  Reliability::Reliable, Durability::Volatile, 10, points_dds_);
    odom_writer_ = createWriter(p, createTopic(p, &nav_msgs_msg_dds__Odometry__desc, odom_dds_),
                                Reliability::Reliable, Durability::Volatile, 100, odom_dds_);
}

void Ros2ScanPublisher::publish(const Scan& scan, const PointCloud& points_sensor) {
    const OdometryMessage odometry(scan.T_world_robot, scan.stamp_s, options_.odom_frame_id,
                                   options_.base_frame_id);
    const CloudMessage cloud(points_sensor, scan.stamp_s, options_.cloud_frame_id);
    const dds_return_t a = dds_write(odom_writer_, odometry.sample());
    const dds_return_t b = dds_write(points_writer_, cloud.sample());
    if (a < 0 || b < 0)
        throw std::runtime_error("DDS write on " + (a < 0 ? odom_dds_ : points_dds_) + ": " +
                                 dds_strretcode(a < 0 ? a : b));
}

namespace {
constexpr double kOdomGraceS = 1.0;  ///< [s] longest wait for an odometry reader once clouds have one
}  // namespace

int Ros2ScanPublisher::waitForSubscribers(double timeout_s, const std::function<bool()>& stop) const {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (matchedReaders(points_writer_) == 0 && !stop() && std::chrono::steady_clock::now() < end)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    // A subscriber's odometry reader is discovered on its own and may match a little later than
    // its cloud reader: a scan published before would reach it without its pose. Wait for one
    // too, briefly (a viewer of the clouds alone has none).
    const auto odom_end =
        std::min(end, std::chrono::steady_clock::now() + std::chrono::duration<double>(kOdomGraceS));
    while (matchedReaders(points_writer_) > 0 && matchedReaders(odom_writer_) == 0 && !stop() &&
           std::chrono::steady_clock::now() < odom_end)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return matchedReaders(points_writer_);
}

void Ros2ScanPublisher::flush(double timeout_s) const {
    const dds_duration_t timeout = static_cast<dds_duration_t>(timeout_s * 1e9);
    dds_wait_for_acks(odom_writer_, timeout);
    dds_wait_for_acks(points_writer_, timeout);
}

}  // namespace stairmap::ros2
