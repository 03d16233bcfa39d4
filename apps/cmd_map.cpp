// `stairmap map`: replays a rawlog through the mapping pipeline and writes the map outputs.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "Commands.h"
#include "io/system/AtomicFile.h"
#include "io/json/LandmarkJson.h"
#include "io/config/MapperConfig.h"
#include "io/system/ProcessMemory.h"
#include "io/system/ProgressBar.h"
#include "io/rawlog/RawlogScanSource.h"
#include "viz/MapOverview.h"
#include "viz/MapScene.h"
#include "pipeline/Mapper.h"
#include "io/json/MapperJson.h"

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

class MapRun {
public:
    explicit MapRun(const MapOptions& opt)
        : opt_(opt),
          params_(opt.config.empty() ? pipeline::MapperParams{} : io::loadMapperParams(opt.config)),
          mapper_(params_, initialLandmarks()) {
        fs::create_directories(opt_.out);
        detections_.open(outPath("detections.jsonl"), std::ios::trunc);
        if (!detections_) throw std::runtime_error(outPath("detections.jsonl") + ": cannot open");
        mapper_.setDetectionCallback([this](const pipeline::DetectionRecord& r) {
            detections_ << io::detectionRecordToJson(r).dump() << '\n' << std::flush;
        });
        mapper_.setLandmarksChangedCallback([this](const LandmarkMap& landmarks) {
            io::saveLandmarkMapAtomic(outPath("landmarks.json"), landmarks);
        });
    }

    int run() {
        const auto t0 = Clock::now();
        const std::optional<io::TumTrajectory> poses = trajectory();
        io::RawlogScanSource source(opt_.rawlog, sourceParams(), poses);
        source.setWarningHandler([this](const std::string& m) { warn(m); });
        io::ProgressBar progress(std::cerr, opt_.progress || io::ProgressBar::stderrIsTty(),
                                 opt_.static_robot ? std::nullopt : logDuration(poses));
        std::optional<std::string> error = replay(source, progress);
        progress.finish();
        processing_s_ = secondsSince(t0);
        writeOutputs(source);
        if (!opt_.quiet) printSummary(source, error);
        if (error) {
            std::cerr << "stairmap map: error: " << *error
                      << " (outputs written for the map up to there)\n";
            return kExitTruncated;
        }
        return 0;
    }

private:
    std::string outPath(const std::string& name) const { return (fs::path(opt_.out) / name).string(); }

    LandmarkMap initialLandmarks() const {
        if (opt_.map_in.empty()) return LandmarkMap(params_.landmarks);
        return io::loadLandmarkMap(opt_.map_in, params_.landmarks);
    }

    io::RawlogSourceParams sourceParams() const {
        io::RawlogSourceParams p;
        p.sensor_label = params_.sensor.label_filter;
        return p;
    }

    std::optional<io::TumTrajectory> trajectory() const {
        if (opt_.static_robot) return staticTrajectory();
        if (!opt_.poses.empty()) return io::TumTrajectory::load(opt_.poses);
        return std::nullopt;
    }

    void warn(const std::string& message) { std::cerr << "stairmap map: warning: " << message << "\n"; }

    std::optional<std::string> replay(io::RawlogScanSource& source, io::ProgressBar& progress) {
        try {
            while (true) {
                const auto t_read = Clock::now();
                std::optional<Scan> scan = source.next();
                read_s_ += secondsSince(t_read);
                if (!scan) return std::nullopt;
                mapper_.processScan(*scan);
                progress.update(mapper_.stats().scans, mapper_.stats().logDuration());
            }
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
    }

    void writeOutputs(const io::RawlogScanSource& source) {
        const auto t0 = Clock::now();
        io::saveLandmarkMapAtomic(outPath("landmarks.json"), mapper_.landmarks());
        mapper_.voxelMap().save(outPath("map.bt"));
        const viz::MapView view = mapView();
        viz::saveMapScene(view, outPath("scene.3Dscene"));
        viz::saveMapOverview(view, outPath("overview.png"));
        output_s_ = secondsSince(t0);
        io::writeTextFileAtomic(outPath("stats.json"), statsJson(source).dump(2) + "\n");
    }

    viz::MapView mapView() const {
        viz::MapView view;
        view.voxels = &mapper_.voxelMap();
        view.staircases = mapper_.landmarks().staircases();
        view.floors = mapper_.landmarks().floors();
        for (const auto& s : mapper_.trajectory()) view.trajectory.push_back(s.position);
        return view;
    }

    nlohmann::json statsJson(const io::RawlogScanSource& source) const {
        const auto& st = mapper_.stats();
        nlohmann::json j = io::mapperStatsToJson(st);
        j["read_ms"] = 1000.0 * read_s_;
        j["output_ms"] = 1000.0 * output_s_;
        j["processing_s"] = processing_s_;
        j["real_time_factor"] = processing_s_ > 0 ? st.logDuration() / processing_s_ : 0.0;
        j["peak_rss_mb"] = io::peakRssBytes() / 1048576.0;
        j["voxel_map"] = {{"leaves", mapper_.voxelMap().numLeaves()},
                          {"memory_mb", mapper_.voxelMap().memoryUsageBytes() / 1048576.0}};
        j["landmarks"] = {{"staircases", mapper_.landmarks().staircases().size()},
                          {"floors", mapper_.landmarks().floors().size()}};
        const auto& ss = source.stats();
        j["source"] = {{"scans_read", ss.scans_read}, {"skipped_no_pose", ss.skipped_no_pose},
                       {"skipped_label", ss.skipped_label}, {"unsupported", ss.unsupported},
                       {"non_finite_dropped", ss.non_finite_dropped}};
        j["params"] = io::mapperParamsToJson(params_);
        return j;
    }

    void printSummary(const io::RawlogScanSource& source, const std::optional<std::string>& error) const;

    MapOptions opt_;
    pipeline::MapperParams params_;
    pipeline::Mapper mapper_;
    std::ofstream detections_;
    double read_s_ = 0.0, processing_s_ = 0.0, output_s_ = 0.0;
};

void MapRun::printSummary(const io::RawlogScanSource& source,
                          const std::optional<std::string>& error) const {
    const auto& st = mapper_.stats();
    std::printf("stairmap map: %s\n", error ? "STOPPED at damaged rawlog" : "done");
    std::printf("  scans %zu (%zu points), skipped without pose %zu, log %.1f s, processed in %.2f s"
                " (%.1fx real time)\n", st.scans, st.points_in, source.stats().skipped_no_pose,
                st.logDuration(), processing_s_,
                processing_s_ > 0 ? st.logDuration() / processing_s_ : 0.0);
    for (const auto& [type, count] : source.stats().unsupported) {
        std::printf("  unsupported observations: %s x %zu\n", type.c_str(), count);
    }
    std::printf("  detector runs %zu, detections %zu, voxel leaves %zu, peak RSS %.0f MB\n",
                st.detector_runs, st.detections, mapper_.voxelMap().numLeaves(),
                io::peakRssBytes() / 1048576.0);
    const auto floors = mapper_.landmarks().floors();
    for (const auto& f : floors) std::printf("  floor %d: z = %.2f m\n", f.id, f.z);
    for (const auto& s : mapper_.landmarks().staircases()) {
        std::printf("  stair #%d: %zu steps, rise %.3f run %.3f width %.2f m, floors %d -> %d, "
                    "seen %d x%s\n", s.id, s.stairs.steps.size(), s.stairs.step_height,
                    s.stairs.step_depth, s.stairs.step_width, s.bottom_floor, s.top_floor,
                    s.observations, s.confirmed ? " (confirmed)" : "");
    }
    std::printf("  outputs in %s\n", opt_.out.c_str());
}

}  // namespace

Command addMapCommand(CLI::App& app) {
    auto opt = std::make_shared<MapOptions>();
    Command command;
    command.cli = app.add_subcommand(
        "map", "Replay a rawlog: voxel map + periodic staircase detection -> landmark map.\n"
               "Writes landmarks.json, map.bt, detections.jsonl, scene.3Dscene, overview.png and\n"
               "stats.json into --out (created if needed; other files there are left alone).\n"
               "Exit codes: 0 ok; 1 the rawlog is truncated/corrupt (reported with the scan\n"
               "index; all outputs written for the map up to there); 2 bad arguments/input.");
    command.cli->add_option("rawlog", opt->rawlog, "MRPT rawlog (.rawlog, plain or gz)")
        ->required()->check(CLI::ExistingFile);
    command.cli->add_option("--poses", opt->poses, "TUM trajectory of the robot (preferred pose "
                            "source; else CObservationRobotPose / odometry in the rawlog)")
        ->check(CLI::ExistingFile);
    command.cli->add_option("--config", opt->config, "INI file ([sensor] [map] [scheduling] "
                            "[detector] [landmarks]); built-in defaults otherwise");
    command.cli->add_option("--map-in", opt->map_in, "landmarks.json of a previous run to "
                            "continue (same IDs; never modified unless it is the output)");
    command.cli->add_option("--out", opt->out, "output directory")->required();
    command.cli->add_flag("--static-robot", opt->static_robot,
                          "the robot did not move: identity pose for every scan (logs without poses)")
        ->excludes("--poses");
    command.cli->add_flag("--progress", opt->progress, "progress bar on stderr even if not a TTY");
    command.cli->add_flag("--quiet", opt->quiet, "no summary on stdout");
    command.run = [opt]() -> int { return MapRun(*opt).run(); };
    return command;
}

}  // namespace stairmap::apps
