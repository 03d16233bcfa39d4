// `stairmap play RAWLOG --ros2`: publishes a rawlog's scans as sensor_msgs/PointCloud2 and its
// poses as nav_msgs/Odometry on ROS 2 (Cyclone DDS, loopback unless CYCLONEDDS_URI is set), at
// the recorded rate x R: the demo and test source for `stairmap live --ros2`.
// Frames: the clouds are in the SENSOR frame given by --config's [sensor] pose_x_m..pose_roll_deg
// (the rawlog's points are read in the robot frame, then moved by T_robot_sensor^-1; without a
// config the sensor frame is the robot frame). `stairmap live --ros2` with the same config gets
// the robot-frame points back. Odometry: base_link (robot) in odom (world), the log's poses.
// Stamps are the log's; with --loop each pass adds the log's duration plus one scan period so
// that stamps keep increasing.
#include <chrono>
#include <iostream>
#include <optional>
#include <string>

#include "Commands.h"
#include "io/config/MapperConfig.h"
#include "io/rawlog/RawlogScanSource.h"
#include "io/system/StopSignals.h"
#include "ros2/Ros2ScanPublisher.h"
#include "ros2/ScanPlayback.h"

namespace stairmap::apps {
namespace {

struct PlayOptions {
    std::string rawlog, poses, config;
    double rate = 1.0;
    bool static_robot = false;
    bool ros2 = false;
    bool loop = false;
    bool quiet = false;
    double wait_subscribers_s = 5.0;
    ros2::Ros2PlayOptions topics;
};

std::optional<io::TumTrajectory> trajectory(const PlayOptions& opt, std::string& input) {
    if (opt.static_robot) {
        io::TumTrajectory still;  // the identity at every time
        still.append(0.0, Eigen::Isometry3d::Identity());
        still.append(1e11, Eigen::Isometry3d::Identity());
        return still;
    }
    if (opt.poses.empty()) return std::nullopt;
    input = opt.poses;
    return io::TumTrajectory::load(opt.poses);
}

int runPlay(const PlayOptions& opt, std::string& input) {
    if (!opt.ros2) throw std::invalid_argument("choose a transport: --ros2 (the only one so far)");
    if (!(opt.rate > 0.0)) throw std::invalid_argument("--rate: must be > 0");
    input = opt.config;
    const pipeline::MapperParams params =
        opt.config.empty() ? pipeline::MapperParams{} : io::loadMapperParams(opt.config);
    const std::optional<io::TumTrajectory> poses = trajectory(opt, input);
    io::RawlogSourceParams source_params;
    source_params.sensor_label = params.sensor.label_filter;
    input = opt.rawlog;
    io::RawlogScanSource probe(opt.rawlog, source_params, poses);  // a missing rawlog fails here

    io::StopSignals signals;
    const auto stop = [&] { return signals.received() != 0; };
    ros2::Ros2ScanPublisher publisher(opt.topics);
    const int subscribers = publisher.waitForSubscribers(opt.wait_subscribers_s, stop);
    if (!opt.quiet)
        std::cerr << "stairmap play: " << subscribers << " subscriber(s) on " << opt.topics.points_topic
                  << ", publishing " << opt.rawlog << " at x" << opt.rate << "\n";
    ros2::PlaybackOptions playback;
    playback.rate = opt.rate;
    playback.T_robot_sensor = ros2::sensorPoseOnRobot(params.sensor);
    std::size_t scans = 0, points = 0;
    for (int pass = 0; pass == 0 || (opt.loop && !stop()); ++pass) {
        io::RawlogScanSource source(opt.rawlog, source_params, poses);
        const ros2::PlaybackResult r = ros2::playScans(source, publisher, playback, stop);
        scans += r.scans;
        points += r.points;
        if (stop()) break;
        if (r.scans == 0)
            throw std::runtime_error(opt.rawlog + ": no 3D scan with a pose (give --poses or --static-robot)");
        // the next pass continues one mean scan period after this one
        const double period = r.scans > 1 ? (r.last_stamp_s - r.first_stamp_s) / double(r.scans - 1) : 0.1;
        playback.stamp_offset_s += r.last_stamp_s - r.first_stamp_s + period;
    }
    publisher.flush(2.0);
    if (!opt.quiet)
        std::cerr << "stairmap play: published " << scans << " clouds (" << points << " points)\n";
    return signals.received() ? 128 + signals.received() : 0;
}

}  // namespace

Command addPlayCommand(CLI::App& app) {
    auto opt = std::make_shared<PlayOptions>();
    Command command;
    CLI::App* cmd = app.add_subcommand(
        "play",
        "Publish a rawlog's scans (sensor_msgs/PointCloud2, in the sensor frame of --config's [sensor] "
        "pose_*) and poses (nav_msgs/Odometry, base_link in odom) on ROS 2 at the recorded rate x R. "
        "Cyclone DDS on ROS_DOMAIN_ID, loopback only (config/cyclonedds_loopback.xml) unless "
        "CYCLONEDDS_URI is set. Exit 0 at the end of the log, 128+N on signal N.");
    command.cli = cmd;
    cmd->add_option("rawlog", opt->rawlog, "MRPT rawlog (plain or .gz)")->required();
    cmd->add_option("--poses", opt->poses, "TUM trajectory of the robot (else poses from the rawlog)");
    cmd->add_option("--config", opt->config, "INI file: [sensor] label_filter and pose_x_m..pose_roll_deg");
    cmd->add_option("--rate", opt->rate, "speed factor on the recorded rate (default 1)");
    cmd->add_flag("--static-robot", opt->static_robot, "the robot does not move: identity pose for every scan");
    cmd->add_flag("--ros2", opt->ros2, "publish on ROS 2 (required: the only transport)");
    cmd->add_option("--points-topic", opt->topics.points_topic, "PointCloud2 topic (default /points)");
    cmd->add_option("--odom-topic", opt->topics.odom_topic, "Odometry topic (default /odom)");
    cmd->add_option("--sensor-frame", opt->topics.cloud_frame_id, "frame_id of the clouds (default lidar)");
    cmd->add_flag("--loop", opt->loop, "start again at the end until interrupted (stamps keep increasing)");
    cmd->add_option("--wait-subscribers", opt->wait_subscribers_s,
                    "[s] wait this long for a subscriber of the clouds before starting, then up to 1 s "
                    "more (within it) for one of the odometry (default 5)");
    cmd->add_flag("--quiet", opt->quiet, "no messages on stderr");
    command.run = [opt, input = command.input] { return runPlay(*opt, *input); };
    return command;
}

}  // namespace stairmap::apps
