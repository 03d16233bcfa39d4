#include "ros2/Ros2Source.h"

#include <chrono>
#include <cmath>

#include "ros2/MessageBuilders.h"

namespace stairmap::ros2 {
namespace {

double monotonicSeconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

constexpr int kTakeBatch = 16;

/// Takes every available sample of `reader` (loaned, returned after `handle` ran on each).
template <class Handle>
void takeAll(dds_entity_t reader, Handle&& handle) {
    for (;;) {
        void* samples[kTakeBatch] = {nullptr};
        dds_sample_info_t infos[kTakeBatch];
        const dds_return_t n = dds_take(reader, samples, infos, kTakeBatch, kTakeBatch);
        if (n <= 0) return;
        for (dds_return_t i = 0; i < n; ++i)
            if (infos[i].valid_data) handle(samples[i]);
        dds_return_loan(reader, samples, n);
        if (n < kTakeBatch) return;
    }
}

}  // namespace

Eigen::Isometry3d sensorPoseOnRobot(const pipeline::SensorParams& s) {
    const double deg = M_PI / 180.0;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = (Eigen::AngleAxisd(s.pose_yaw_deg * deg, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(s.pose_pitch_deg * deg, Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(s.pose_roll_deg * deg, Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    T.translation() = Eigen::Vector3d(s.pose_x_m, s.pose_y_m, s.pose_z_m);
    return T;
}

Ros2Source::Ros2Source(const Ros2SourceOptions& options)
    : options_(options),
      points_dds_(ddsTopicName(options.points_topic)),
      odom_dds_(ddsTopicName(options.odom_topic)),
      poses_(options.poses) {
    for (const char* name : {"clouds_received", "scans_pushed", "clouds_without_xyz", "malformed_clouds",
                             "clouds_without_pose", "odometry_received", "malformed_odometry",
                             "odometry_out_of_order", "non_finite_points"})
        counters_[name] = 0;
}

std::string Ros2Source::describe() const {
    return "ROS 2 topics " + options_.points_topic + " (PointCloud2) and " +
           (options_.static_robot ? std::string("a static robot") : options_.odom_topic + " (Odometry)") +
           " on DDS domain " + std::to_string(rosDomainId());
}

std::map<std::string, std::size_t> Ros2Source::counters() const {
    std::lock_guard<std::mutex> lock(counters_mutex_);
    return counters_;
}

void Ros2Source::count(const std::string& name, std::size_t n) {
    std::lock_guard<std::mutex> lock(counters_mutex_);
    counters_[name] += n;
}

void Ros2Source::run(live::ScanSink& sink, const std::atomic<bool>& stop) {
    DdsEntity participant = createParticipant();
    const dds_entity_t p = participant.get();
    const dds_entity_t cloud_reader =
        createReader(p, createTopic(p, &sensor_msgs_msg_dds__PointCloud2__desc, points_dds_),
                     Reliability::BestEffort, Durability::Volatile, 10, options_.points_topic);
    const dds_entity_t odom_reader =
        createReader(p, createTopic(p, &nav_msgs_msg_dds__Odometry__desc, odom_dds_),
                     Reliability::BestEffort, Durability::Volatile, 200, options_.odom_topic);
    DdsEntity waitset(dds_create_waitset(p));
    dds_waitset_attach(waitset.get(), dds_create_readcondition(cloud_reader, DDS_ANY_STATE), 0);
    dds_waitset_attach(waitset.get(), dds_create_readcondition(odom_reader, DDS_ANY_STATE), 0);
    while (!stop.load()) {
        dds_waitset_wait(waitset.get(), nullptr, 0, DDS_MSECS(100));
        takeOdometry(odom_reader);  // poses first: a cloud may need the odometry that came with it
        takeClouds(cloud_reader);
        releaseWaiting(sink);
    }
}

void Ros2Source::takeOdometry(dds_entity_t reader) {
    takeAll(reader, [&](const void* sample) {
        const auto& odometry = *static_cast<const nav_msgs_msg_dds__Odometry_*>(sample);
        count("odometry_received");
        Eigen::Isometry3d T_world_robot;
        if (!odometryPose(odometry, T_world_robot)) return count("malformed_odometry");
        if (!poses_.add(headerStamp(odometry.header), T_world_robot)) count("odometry_out_of_order");
    });
}

void Ros2Source::takeClouds(dds_entity_t reader) {
    takeAll(reader, [&](const void* sample) { onCloud(sample); });
}

void Ros2Source::onCloud(const void* sample) {
    const auto& cloud = *static_cast<const sensor_msgs_msg_dds__PointCloud2_*>(sample);
    count("clouds_received");
    const CloudDecodeResult decoded =
        decodePointCloud(cloudLayout(cloud), cloud.data._buffer, cloud.data._length, options_.limits);
    count("non_finite_points", decoded.dropped_non_finite);
    if (decoded.status == CloudDecodeStatus::NoXyz) return count("clouds_without_xyz");
    if (decoded.status != CloudDecodeStatus::Ok) return count("malformed_clouds");
    waiting_.push_back({headerStamp(cloud.header), decoded.points, monotonicSeconds()});
    while (waiting_.size() > options_.max_waiting_clouds) {
        waiting_.pop_front();
        count("clouds_without_pose");
    }
}

void Ros2Source::releaseWaiting(live::ScanSink& sink) {
    const double now = monotonicSeconds();
    while (!waiting_.empty()) {
        Waiting& cloud = waiting_.front();
        Eigen::Isometry3d T_world_robot = Eigen::Isometry3d::Identity();
        const PoseLookup found =
            options_.static_robot ? PoseLookup::Found : poses_.lookup(cloud.stamp_s, T_world_robot);
        if (found == PoseLookup::NotYet && now - cloud.arrived_s < options_.pose_wait_s) return;
        if (found != PoseLookup::Found) {
            count("clouds_without_pose");
            waiting_.pop_front();
            continue;
        }
        Scan scan;
        scan.index = next_index_++;
        scan.stamp_s = cloud.stamp_s;
        scan.sensor_label = options_.sensor_label;
        scan.T_world_robot = T_world_robot;
        const Eigen::Isometry3f T = options_.T_robot_sensor.cast<float>();
        scan.points_robot.reserve(cloud.points_sensor.size());
        for (const Eigen::Vector3f& p : cloud.points_sensor) scan.points_robot.push_back(T * p);
        waiting_.pop_front();
        sink.push(std::move(scan));
        count("scans_pushed");
    }
}

std::unique_ptr<live::LiveSource> makeRos2Source(const Ros2SourceOptions& options) {
    return std::make_unique<Ros2Source>(options);
}

}  // namespace stairmap::ros2
