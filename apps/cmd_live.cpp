// `stairmap live`: maps scans as they arrive from one live source with the same Mapper as `map`.
// Bad input (config, --map-in, the source's file or poses) fails before the output folder is
// created and locked. landmarks.json follows every landmark change, stats.json is rewritten every
// few seconds, and every output (map.bt, scene.3Dscene, overview.png too) at the end and on
// SIGUSR1. SIGINT/SIGTERM end the run after the scan in hand; outputs are written, exit 0.
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "Commands.h"
#include "RunInputs.h"
#include "LiveReport.h"
#include "io/config/MapperConfig.h"
#include "io/follow/RawlogFollowSource.h"
#include "io/json/LandmarkJson.h"
#include "io/system/AtomicFile.h"
#include "io/system/DirectoryLock.h"
#include "io/system/SnapshotSignal.h"
#include "io/system/StopSignals.h"
#include "live/LiveRunner.h"
#include "mapout/MapOutputs.h"
#include "pipeline/Mapper.h"
#include "ros2/Ros2LandmarkPublisher.h"
#include "ros2/Ros2Source.h"
#include "sensors/SensorSource.h"

namespace stairmap::apps {
namespace {

struct LiveOptions {
    std::string follow;  ///< --follow FILE.rawlog
    std::string sensor;  ///< --sensor F.ini (MRPT drivers, rawlog-grabber sections)
    std::string sensor_stamps = "arrival";  ///< --sensor-stamps arrival|sensor
    // (--sensor and --ros2 add their option here and one branch in makeSource.)
    std::string poses, config, map_in, out;
    bool static_robot = false, progress = false, quiet = false;
    double duration_s = 0.0, idle_timeout_s = 5.0, pose_wait_s = 5.0, stats_period_s = 2.0;
    std::size_t max_scans = 0, queue = 4;
    bool ros2 = false;  ///< --ros2: clouds and odometry from ROS 2 topics, landmarks published there
    std::string points_topic = "/points", odom_topic = "/odom", robot_name, frame_id = "map";
};

constexpr int kExitSourceFailed = 1;  // the source broke (corrupt file); outputs written

/// The run's one live source, from the options; checks its input without waiting, so bad input
/// fails before any output is touched. A new source (--sensor, --ros2) is one branch here.
std::unique_ptr<live::LiveSource> makeSource(const LiveOptions& opt,
                                             const pipeline::MapperParams& params,
                                             std::string& input) {
    if (opt.ros2 && (!opt.follow.empty() || !opt.sensor.empty()))
        throw std::invalid_argument("give one source: --follow, --sensor or --ros2");
    if (opt.ros2) {
        ros2::Ros2SourceOptions p;
        p.points_topic = opt.points_topic;
        p.odom_topic = opt.odom_topic;
        p.T_robot_sensor = ros2::sensorPoseOnRobot(params.sensor);  // no TF: [sensor] pose_*
        p.static_robot = opt.static_robot;
        p.pose_wait_s = opt.pose_wait_s;
        if (!params.sensor.label_filter.empty()) p.sensor_label = params.sensor.label_filter;
        return ros2::makeRos2Source(p);
    }
    if (!opt.follow.empty()) {
        input = opt.follow;
        io::checkFollowableRawlog(opt.follow);
        io::RawlogFollowParams p;
        p.file.idle_timeout_s = opt.idle_timeout_s;
        p.rawlog.sensor_label = params.sensor.label_filter;
        p.poses_path = opt.poses;
        p.poses.wait_s = opt.pose_wait_s;
        p.static_robot = opt.static_robot;
        p.on_warning = [](const std::string& m) { std::cerr << "stairmap live: warning: " << m << "\n"; };
        return std::make_unique<io::RawlogFollowSource>(opt.follow, p);
    }
    if (!opt.sensor.empty()) {
        input = opt.sensor;
        sensors::SensorSourceOptions p;
        p.poses_path = opt.poses;
        p.static_robot = opt.static_robot;
        p.pose_wait.max_wait_s = opt.pose_wait_s;
        p.stamps = opt.sensor_stamps == "sensor" ? sensors::SensorSourceOptions::Stamps::Sensor
                                                 : sensors::SensorSourceOptions::Stamps::Arrival;
        p.sensor_label = params.sensor.label_filter;
        p.T_robot_sensor = sensors::sensorPoseOnRobot(params.sensor);
        return sensors::makeSensorSource(opt.sensor, p);
    }
    throw std::runtime_error("no source: give exactly one of --follow FILE.rawlog, --sensor F.ini, --ros2");
}

/// landmarks.json rewritten atomically on every change (a run killed outright keeps the latest).
class LandmarkFileWriter : public live::LandmarkListener {
public:
    explicit LandmarkFileWriter(std::string path) : path_(std::move(path)) {}
    void onLandmarks(const LandmarkMap& landmarks, double) override {
        io::saveLandmarkMapAtomic(path_, landmarks);
    }

private:
    std::string path_;
};

class LiveRun {
public:
    LiveRun(const LiveOptions& opt, std::string& input)
        : opt_(opt), input_(input), params_(loadParams()), mapper_(params_, initialLandmarks()) {}

    int run() {
        io::StopSignals stop;
        io::SnapshotSignal snapshot;
        if (!opt_.poses.empty() && !std::filesystem::is_regular_file(opt_.poses))
            throw std::runtime_error(opt_.poses + ": no such TUM trajectory file");
        std::unique_ptr<live::LiveSource> source = makeSource(opt_, params_, input_);
        std::unique_ptr<live::LandmarkListener> publisher = makePublisher();  // before any output
        std::filesystem::create_directories(opt_.out);
        const io::DirectoryLock lock(opt_.out);  // a second run on this folder fails here
        io::removeStaleTempFiles(opt_.out);
        LandmarkFileWriter landmarks_file(outPath("landmarks.json"));
        live::LiveRunner runner(mapper_, *source, runnerParams());
        runner.addListener(landmarks_file);
        if (publisher) runner.addListener(*publisher);
        runner.setStopCheck([&stop] { return stop.received() != 0; });
        runner.setTickCallback([&](const live::LiveStatus& s) { onTick(s, *source, snapshot); });
        const live::LiveEnd end = runner.run();
        const std::string ended = endReason(end, runner.sourceError(), stop.received());
        if (status_line_) std::cerr << "\r\033[K" << std::flush;
        const live::LiveStatus final_status = runner.status();
        writeOutputs(final_status, *source, ended);
        if (!opt_.quiet) printLiveSummary(mapper_, final_status, source->describe(), ended, opt_.out);
        if (runner.sourceError()) {
            std::cerr << "stairmap live: error: " << *runner.sourceError()
                      << " (outputs written for the map up to there)\n";
            return kExitSourceFailed;
        }
        return 0;
    }

private:
    std::string outPath(const std::string& name) const { return mapout::outputPath(opt_.out, name); }

    /// --ros2: MarkerArray and StaircaseArray on /[robot/]stairmap/... (ros2/Ros2LandmarkPublisher.h).
    std::unique_ptr<live::LandmarkListener> makePublisher() const {
        if (!opt_.ros2) return nullptr;
        ros2::Ros2PublisherOptions p;
        p.robot_name = opt_.robot_name;
        p.frame_id = opt_.frame_id;
        return ros2::makeRos2Publisher(p);
    }

    pipeline::MapperParams loadParams() const { return loadRunParams(opt_.config, input_); }

    LandmarkMap initialLandmarks() const {
        return loadRunLandmarks(opt_.map_in, params_.landmarks, input_);
    }

    live::LiveRunnerParams runnerParams() const {
        live::LiveRunnerParams p;
        p.queue_capacity = opt_.queue;
        p.duration_s = opt_.duration_s;
        p.max_scans = opt_.max_scans;
        p.tick_period_s = 1.0;
        return p;
    }

    static std::string endReason(live::LiveEnd end, const std::optional<std::string>& error,
                                 int signal) {
        if (error) return "source failed";
        if (end == live::LiveEnd::StopRequested)
            return signal == SIGINT ? "stopped by SIGINT" : "stopped by SIGTERM";
        return live::toString(end);
    }

    /// Every second on the mapping thread: status line, stats.json every stats_period_s, and
    /// every output when SIGUSR1 asked for a snapshot.
    void onTick(const live::LiveStatus& s, const live::LiveSource& source,
                io::SnapshotSignal& snapshot) {
        if (opt_.progress || ::isatty(STDERR_FILENO)) {
            std::cerr << "\r\033[K" << liveStatusLine(s) << std::flush;
            status_line_ = true;
        }
        if (snapshot.take()) {
            writeOutputs(s, source, "running");
            last_stats_s_ = s.elapsed_s;
        } else if (s.elapsed_s - last_stats_s_ >= opt_.stats_period_s) {
            writeStats(s, source, "running");
            last_stats_s_ = s.elapsed_s;
        }
    }

    void writeStats(const live::LiveStatus& s, const live::LiveSource& source,
                    const std::string& ended) {
        io::writeTextFileAtomic(
            outPath("stats.json"),
            liveStatsJson(mapper_, s, source.describe(), opt_.queue, ended).dump(2) + "\n");
    }

    void writeOutputs(const live::LiveStatus& s, const live::LiveSource& source,
                      const std::string& ended) {
        mapout::writeMapOutputs(mapper_, opt_.out);
        writeStats(s, source, ended);
    }

    LiveOptions opt_;
    std::string& input_;  // the file being read, for errors that cannot name it (Commands.h)
    pipeline::MapperParams params_;
    pipeline::Mapper mapper_;
    double last_stats_s_ = 0.0;
    bool status_line_ = false;
};

void addLiveOptions(CLI::App& cmd, LiveOptions& opt) {
    cmd.add_option("--follow", opt.follow,
                   "a plain (not gzip) rawlog that is still being written: objects are mapped as "
                   "they are completed; the run ends when it stops growing (--idle-timeout)");
    cmd.add_flag("--ros2", opt.ros2,
                 "ROS 2 topics (Cyclone DDS, ROS_DOMAIN_ID; loopback unless CYCLONEDDS_URI is set): "
                 "sensor_msgs/PointCloud2 in the sensor frame of [sensor] pose_*, nav_msgs/Odometry; "
                 "publishes /stairmap/markers (MarkerArray) and /stairmap/staircases");
    cmd.add_option("--points-topic", opt.points_topic, "--ros2: PointCloud2 topic (default /points)");
    cmd.add_option("--odom-topic", opt.odom_topic, "--ros2: Odometry topic (default /odom)");
    cmd.add_option("--robot-name", opt.robot_name, "--ros2: publish under /NAME/stairmap/...");
    cmd.add_option("--frame-id", opt.frame_id, "--ros2: frame_id of what is published (default map)");
    cmd.add_option("--sensor", opt.sensor,
                   "MRPT sensor drivers configured as for rawlog-grabber (every section but [global] "
                   "is one sensor, e.g. driver = CVelodyneScanner on live UDP or replaying "
                   "pcap_input; config/sensors/vlp16_pcap.ini); needs --poses or --static-robot")
        ->excludes("--follow");
    cmd.add_option("--sensor-stamps", opt.sensor_stamps,
                   "--sensor: stamp scans with the computer clock on arrival (arrival, default) or "
                   "keep the driver's stamps (sensor; MRPT's Velodyne driver switches to GPS time "
                   "once it has a fix); --poses must use the same clock")
        ->check(CLI::IsMember({"arrival", "sensor"}));
    cmd.add_option("--poses", opt.poses,
                   "TUM trajectory of the robot, may itself be growing (else "
                   "CObservationRobotPose / odometry in the rawlog)");
    cmd.add_flag("--static-robot", opt.static_robot,
                 "the robot does not move: identity pose for every scan")
        ->excludes("--poses");
    cmd.add_option("--config", opt.config, "INI file (as `map`); built-in defaults otherwise");
    cmd.add_option("--map-in", opt.map_in, "landmarks.json of a previous run to continue");
    cmd.add_option("--out", opt.out, "output directory")->required();
    cmd.add_option("--duration", opt.duration_s, "end the run after S seconds [s]")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--max-scans", opt.max_scans, "end the run after N scans are mapped");
    cmd.add_option("--idle-timeout", opt.idle_timeout_s,
                   "--follow: end when the file has not grown for S seconds [s] (default 5)")
        ->check(CLI::PositiveNumber);
    cmd.add_option("--pose-wait", opt.pose_wait_s,
                   "--poses: a scan waits for its pose while the TUM file grows; gives up after "
                   "S seconds without growth [s] (default 5; the scan is then counted, skipped); "
                   "--sensor: S seconds after the scan arrived; "
                   "--ros2: a cloud waits this long for odometry at or after its stamp")
        ->check(CLI::NonNegativeNumber);
    cmd.add_option("--queue", opt.queue, "input queue capacity [scans] (default 4)")
        ->check(CLI::Range(1, 1000));
    cmd.add_option("--stats-every", opt.stats_period_s, "rewrite stats.json every S seconds [s] "
                                                        "(default 2)")
        ->check(CLI::PositiveNumber);
    cmd.add_flag("--progress", opt.progress, "status line on stderr even if not a TTY");
    cmd.add_flag("--quiet", opt.quiet, "no summary on stdout");
}

}  // namespace

Command addLiveCommand(CLI::App& app) {
    auto opt = std::make_shared<LiveOptions>();
    Command command;
    command.cli = app.add_subcommand(
        "live",
        "Map scans as they arrive from one live source (the same mapper as `map`).\n"
        "Source (exactly one): --follow FILE.rawlog, --sensor F.ini, or --ros2 (ROS 2 topics;\n"
        "see README \"ROS 2\").\n"
        "Writes into --out (one run per folder, lock file .stairmap.lock): landmarks.json on\n"
        "every landmark change, stats.json every few seconds (scans/s, lag, dropped scans,\n"
        "latency median/p95, source counters, peak RSS), and landmarks.json, map.bt,\n"
        "scene.3Dscene, overview.png, stats.json at the end and on SIGUSR1; all atomically.\n"
        "Ends when the source ends, after --duration / --max-scans, or on SIGINT/SIGTERM\n"
        "(the scan in hand is finished, every output written).\n"
        "Exit codes: 0 ok (also when stopped by a signal); 1 the source failed (e.g. corrupt\n"
        "rawlog; outputs written for the map up to there); 2 bad arguments/input (nothing\n"
        "written).");
    addLiveOptions(*command.cli, *opt);
    command.run = [opt, input = command.input]() -> int { return LiveRun(*opt, *input).run(); };
    return command;
}

}  // namespace stairmap::apps
