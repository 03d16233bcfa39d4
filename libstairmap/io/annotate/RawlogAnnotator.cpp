#include "io/annotate/RawlogAnnotator.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation3DScene.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "io/config/MapperConfig.h"
#include "io/rawlog/ObservationToPoints.h"
#include "io/rawlog/RawlogScanSource.h"
#include "io/rawlog/TumTrajectory.h"
#include "pipeline/Mapper.h"
#include "viz/ViewerScene.h"

namespace stairmap::io {
namespace {

using SceneList = std::vector<mrpt::obs::CObservation3DScene::Ptr>;

/// The run's detections (blue step edges, world frame) and the landmarks so far.
mrpt::obs::CObservation3DScene::Ptr runScene(const pipeline::DetectionRun& run,
                                             const LandmarkMap& landmarks,
                                             const std::string& label) {
    auto obs = mrpt::obs::CObservation3DScene::Create();
    obs->sensorLabel = label;
    obs->timestamp = mrpt::Clock::fromDouble(run.stamp_s);
    obs->scene = mrpt::opengl::COpenGLScene::Create();
    auto edges = mrpt::opengl::CSetOfLines::Create();
    edges->setLineWidth(4.0f);
    edges->setColor_u8(60, 120, 255);
    for (const auto& r : run.records)
        for (const auto& e : r.staircase_world.steps)
            edges->appendLine(e.start.x(), e.start.y(), e.start.z(), e.end.x(), e.end.y(), e.end.z());
    edges->setName(label + "/detections");
    obs->scene->insert(edges);
    // MRPT 2.5 does not serialize a CObservation3DScene's sensorLabel: the object names carry it.
    auto map = viz::landmarkObjects(landmarks.staircases(), -1);
    map->setName(label + "/landmarks");
    obs->scene->insert(map);
    return obs;
}

/// Pass 1: map the log; scenes keyed by the scan index of their detector run.
std::map<std::size_t, SceneList> mapLog(const AnnotateOptions& o,
                                        const pipeline::MapperParams& params, AnnotateStats& stats) {
    RawlogSourceParams sp;
    sp.sensor_label = params.sensor.label_filter;
    std::optional<TumTrajectory> poses;
    if (!o.poses.empty()) poses = TumTrajectory::load(o.poses);
    RawlogScanSource source(o.in, sp, poses);
    pipeline::Mapper mapper(params);
    std::map<std::size_t, SceneList> scenes;
    mapper.setDetectionRunCallback([&](const pipeline::DetectionRun& run) {
        ++stats.detector_runs;
        stats.detections += run.records.size();
        scenes[run.scan_index].push_back(runScene(run, mapper.landmarks(), o.label));
    });
    while (auto scan = source.next()) mapper.processScan(*scan);  // damage throws, naming in
    return scenes;
}

bool isGzip(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[2] = {0, 0};
    in.read(reinterpret_cast<char*>(magic), 2);
    return in.gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
}

/// Counts the 3D scans of one observation exactly as RawlogScanSource numbers them.
bool isNumberedScan(const mrpt::obs::CObservation& obs, const std::string& label) {
    if (dynamic_cast<const mrpt::obs::CObservationRobotPose*>(&obs)) return false;
    if (!isConvertible3DObservation(obs)) return false;
    return label.empty() || obs.sensorLabel == label;
}

/// Pass 2: copy every object, appending the scenes after the object holding their scan.
void copyWithScenes(const AnnotateOptions& o, const std::string& label_filter,
                    std::map<std::size_t, SceneList>& scenes, AnnotateStats& stats) {
    mrpt::io::CFileGZInputStream in_file(o.in);
    auto in = mrpt::serialization::archiveFrom(in_file);
    mrpt::io::CFileGZOutputStream out_file;
    if (!out_file.open(o.out, isGzip(o.in) ? 1 : 0))
        throw std::runtime_error(o.out + ": cannot open for writing");
    auto out = mrpt::serialization::archiveFrom(out_file);
    std::size_t next_scan = 0;
    for (;;) {
        mrpt::serialization::CSerializable::Ptr object;
        const auto start = in_file.getPosition();
        try {
            object = in.ReadObject();
        } catch (const std::exception& e) {
            if (in_file.getPosition() == start) break;  // nothing of a new object: clean end
            throw std::runtime_error(o.in + ": corrupt at object " +
                                     std::to_string(stats.objects_copied) + ": " + e.what());
        }
        if (!object) break;
        out.WriteObject(object.get());
        ++stats.objects_copied;
        std::vector<const mrpt::obs::CObservation*> observations;
        if (const auto* sf = dynamic_cast<const mrpt::obs::CSensoryFrame*>(object.get())) {
            for (const auto& obs : *sf) if (obs) observations.push_back(obs.get());
        } else if (const auto* obs = dynamic_cast<const mrpt::obs::CObservation*>(object.get())) {
            observations.push_back(obs);
        }
        for (const auto* obs : observations) {
            if (!isNumberedScan(*obs, label_filter)) continue;
            const auto it = scenes.find(next_scan++);
            if (it == scenes.end()) continue;
            for (const auto& scene : it->second) out.WriteObject(scene.get());
            stats.scenes_inserted += it->second.size();
        }
    }
}

}  // namespace

AnnotateStats annotateRawlog(const AnnotateOptions& o) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(o.out, ec) && fs::equivalent(o.in, o.out, ec))
        throw std::runtime_error(o.out + ": the output must not be the input rawlog");
    const pipeline::MapperParams params =
        o.config.empty() ? pipeline::MapperParams{} : loadMapperParams(o.config);
    AnnotateStats stats;
    auto scenes = mapLog(o, params, stats);
    copyWithScenes(o, params.sensor.label_filter, scenes, stats);
    return stats;
}

}  // namespace stairmap::io
