// `stairmap map`: replays a rawlog through the mapping pipeline and writes the map outputs.
// Bad input never touches an existing map: config, --map-in, poses and the rawlog's first 3D scan
// are read before the output folder is created and locked (one run per folder). Outputs are
// replaced atomically; SIGINT/SIGTERM end the replay after the scan in hand (exit 128 + signal).
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "Commands.h"
#include "RunInputs.h"
#include "MapReport.h"
#include "io/config/MapperConfig.h"
#include "io/json/LandmarkJson.h"
#include "io/json/MapperJson.h"
#include "io/rawlog/RawlogScanSource.h"
#include "io/system/AtomicFile.h"
#include "io/system/AtomicOutputStream.h"
#include "io/system/DirectoryLock.h"
#include "io/system/ProgressBar.h"
#include "io/system/StopSignals.h"
#include "mapout/MapOutputs.h"
#include "pipeline/Mapper.h"

namespace stairmap::apps {
namespace {

namespace fs = std::filesystem;

struct MapOptions {
    std::string rawlog, poses, config, map_in, out;
    bool static_robot = false;
    bool progress = false;
    bool quiet = false;
};

constexpr int kExitTruncated = 1;  // the rawlog was damaged; the map up to the damage was written

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The log's duration from its trajectory (for the progress ETA); unknown without one.
std::optional<double> logDuration(const std::optional<io::TumTrajectory>& poses) {
    if (!poses || poses->poses().size() < 2) return std::nullopt;
    return poses->poses().back().stamp_s - poses->poses().front().stamp_s;
}

/// A static robot: the identity pose at every time (for logs without poses).
io::TumTrajectory staticTrajectory() {
    io::TumTrajectory trajectory;
    trajectory.append(0.0, Eigen::Isometry3d::Identity());
    trajectory.append(1e11, Eigen::Isometry3d::Identity());
    return trajectory;
}

/// Test hook: STAIRMAP_TEST_SCAN_DELAY_MS=N sleeps N ms after each scan, so that tests can send
/// a signal while a run is surely in progress. Unset (always, outside tests): no delay.
std::chrono::milliseconds testScanDelay() {
    const char* text = std::getenv("STAIRMAP_TEST_SCAN_DELAY_MS");
    return std::chrono::milliseconds(text ? std::strtol(text, nullptr, 10) : 0);
}

/// Why a rawlog gave no scan to map, from what its reader saw.
std::string noScanReason(const io::RawlogSourceStats& s) {
    if (s.objects_read == 0) return "it is empty";
    std::string why = std::to_string(s.objects_read) + " objects read, " +
                      std::to_string(s.scans_read) + " 3D scans";
    if (s.skipped_no_pose > 0)
        why += ", " + std::to_string(s.skipped_no_pose) +
               " without a pose "
               "(give --poses, or --static-robot)";
    if (s.skipped_label > 0) why += ", " + std::to_string(s.skipped_label) + " with another label";
    for (const auto& [type, count] : s.unsupported)
        why += ", " + type + " x" + std::to_string(count);
    return why;
}

class MapRun {
  public:
    MapRun(const MapOptions& opt, std::string& input)
        : opt_(opt), input_(input), params_(loadParams()), mapper_(params_, initialLandmarks()) {}

    int run() {
        io::StopSignals stop;
        const auto t0 = Clock::now();
        const std::optional<io::TumTrajectory> poses = trajectory();
        input_ = opt_.rawlog;
        io::RawlogScanSource source(opt_.rawlog, sourceParams(), poses);
        source.setWarningHandler([this](const std::string& m) { warn(m); });
        std::optional<Scan> first = probe(source);  // bad input fails here, outputs untouched
        if (stop.received()) return 128 + stop.received();  // nothing mapped: nothing written

        fs::create_directories(opt_.out);
        const io::DirectoryLock lock(opt_.out);  // a second run on this folder fails here
        io::removeStaleTempFiles(opt_.out);      // left by a run killed outright
        io::AtomicOutputStream detections(outPath("detections.jsonl"));
        connectOutputs(detections.stream());
        io::ProgressBar progress(std::cerr, opt_.progress || io::ProgressBar::stderrIsTty(),
                                 opt_.static_robot ? std::nullopt : logDuration(poses));
        const std::optional<std::string> error = replay(source, std::move(*first), progress, stop);
        progress.finish();
        times_.processing_s = secondsSince(t0);
        writeOutputs(source, detections);
        if (!opt_.quiet) printMapSummary(mapper_, source, times_, opt_.out, error, stop.received());
        return exitStatus(error, stop.received());
    }

  private:
    std::string outPath(const std::string& name) const {
        return mapout::outputPath(opt_.out, name);
    }

    pipeline::MapperParams loadParams() const { return loadRunParams(opt_.config, input_); }

    LandmarkMap initialLandmarks() const {
        return loadRunLandmarks(opt_.map_in, params_.landmarks, input_);
    }

    io::RawlogSourceParams sourceParams() const {
        io::RawlogSourceParams p;
        p.sensor_label = params_.sensor.label_filter;
        return p;
    }

    std::optional<io::TumTrajectory> trajectory() const {
        if (opt_.static_robot) return staticTrajectory();
        input_ = opt_.poses;
        if (!opt_.poses.empty()) return io::TumTrajectory::load(opt_.poses);
        return std::nullopt;
    }

    void warn(const std::string& message) {
        std::cerr << "stairmap map: warning: " << message << "\n";
    }

    /// The first scan to map. A file that is not a rawlog, is damaged before its first scan, or
    /// holds no 3D scan with a pose is bad input: thrown before any output is touched.
    std::optional<Scan> probe(io::RawlogScanSource& source) {
        const std::string untouched = "; nothing mapped, " + opt_.out + " left untouched";
        std::optional<Scan> first;
        try {
            const auto t_read = Clock::now();
            first = source.next();
            times_.read_s += secondsSince(t_read);
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(std::string(e.what()) +
                                     " (not a rawlog, or damaged before its first 3D scan)" +
                                     untouched);
        }
        if (!first) {
            throw std::runtime_error(opt_.rawlog + ": no 3D scan with a pose to map (" +
                                     noScanReason(source.stats()) + ")" + untouched);
        }
        return first;
    }

    /// Detections go to the run's detections.jsonl; landmarks.json follows every change, so a
    /// run killed outright still leaves the latest landmark map.
    void connectOutputs(std::ostream& detections) {
        mapper_.setDetectionCallback([&detections](const pipeline::DetectionRecord& r) {
            detections << io::detectionRecordToJson(r).dump() << '\n' << std::flush;
        });
        mapper_.setLandmarksChangedCallback([this](const LandmarkMap& landmarks) {
            io::saveLandmarkMapAtomic(outPath("landmarks.json"), landmarks);
        });
    }

    /// Maps `scan` and the ones after it until the end of the log, a stop signal (after the scan in
    /// hand) or damage in the rawlog (returned as the error text).
    std::optional<std::string> replay(io::RawlogScanSource& source, Scan scan,
                                      io::ProgressBar& progress, const io::StopSignals& stop) {
        const auto delay = testScanDelay();
        for (;;) {
            mapper_.processScan(scan);
            progress.update(mapper_.stats().scans, mapper_.stats().logDuration());
            if (delay.count() > 0) std::this_thread::sleep_for(delay);
            if (stop.received()) return std::nullopt;
            const auto t_read = Clock::now();
            std::optional<Scan> next;
            try {
                next = source.next();
            } catch (const std::runtime_error& e) {
                return std::string(e.what());
            }
            times_.read_s += secondsSince(t_read);
            if (!next) return std::nullopt;
            scan = std::move(*next);
        }
    }

    void writeOutputs(const io::RawlogScanSource& source, io::AtomicOutputStream& detections) {
        const auto t0 = Clock::now();
        mapout::writeMapOutputs(mapper_, opt_.out);
        detections.commit();
        times_.output_s = secondsSince(t0);
        io::writeTextFileAtomic(outPath("stats.json"),
                                mapStatsJson(mapper_, source, params_, times_).dump(2) + "\n");
    }

    int exitStatus(const std::optional<std::string>& error, int signal) const {
        if (signal != 0) {
            std::cerr << "stairmap map: stopped by " << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                      << " after scan " << mapper_.stats().scans
                      << " (outputs written for the map so far)\n";
            return 128 + signal;
        }
        if (!error) return 0;
        std::cerr << "stairmap map: error: " << *error
                  << " (outputs written for the map up to there)\n";
        return kExitTruncated;
    }

    MapOptions opt_;
    std::string& input_;  // the file being read, for errors that cannot name it (Commands.h)
    pipeline::MapperParams params_;
    pipeline::Mapper mapper_;
    MapRunTimes times_;
};

}  // namespace

Command addMapCommand(CLI::App& app) {
    auto opt = std::make_shared<MapOptions>();
    Command command;
    command.cli = app.add_subcommand(
        "map",
        "Replay a rawlog: voxel map + periodic staircase detection -> landmark map.\n"
        "Writes landmarks.json, map.bt, detections.jsonl, scene.3Dscene, overview.png and\n"
        "stats.json into --out (created if needed; other files there are left alone), each\n"
        "replaced atomically; one run per --out at a time (lock file .stairmap.lock).\n"
        "Exit codes: 0 ok; 1 the rawlog is truncated/corrupt (reported with the scan\n"
        "index; all outputs written for the map up to there); 2 bad arguments/input (not a\n"
        "rawlog, no 3D scan with a pose, --out in use: nothing written); 130/143 stopped by\n"
        "SIGINT/SIGTERM (after the scan in hand; all outputs written for the map so far).");
    command.cli->add_option("rawlog", opt->rawlog, "MRPT rawlog (.rawlog, plain or gz)")
        ->required()
        ->check(CLI::ExistingFile);
    command.cli
        ->add_option("--poses", opt->poses,
                     "TUM trajectory of the robot (preferred pose "
                     "source; else CObservationRobotPose / odometry in the rawlog)")
        ->check(CLI::ExistingFile);
    command.cli->add_option("--config", opt->config,
                            "INI file ([sensor] [map] [scheduling] "
                            "[detector] [landmarks] [floors]); built-in defaults otherwise");
    command.cli->add_option("--map-in", opt->map_in,
                            "landmarks.json of a previous run to "
                            "continue (same IDs; never modified unless it is the output)");
    command.cli->add_option("--out", opt->out, "output directory")->required();
    command.cli
        ->add_flag("--static-robot", opt->static_robot,
                   "the robot did not move: identity pose for every scan (logs without poses)")
        ->excludes("--poses");
    command.cli->add_flag("--progress", opt->progress, "progress bar on stderr even if not a TTY");
    command.cli->add_flag("--quiet", opt->quiet, "no summary on stdout");
    command.run = [opt, input = command.input]() -> int { return MapRun(*opt, *input).run(); };
    return command;
}

}  // namespace stairmap::apps
