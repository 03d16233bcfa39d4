#include "replay/ReplaySession.h"

#include <stdexcept>

#include "io/config/MapperConfig.h"
#include "io/json/LandmarkJson.h"
#include "io/rawlog/RawlogScanSource.h"
#include "io/rawlog/TumTrajectory.h"

namespace stairmap::replay {

ReplaySession::ReplaySession(ReplayOptions options)
    : options_(std::move(options)),
      params_(options_.config.empty() ? pipeline::MapperParams{}
                                      : io::loadMapperParams(options_.config)) {
    if (!options_.poses.empty())
        poses_ = std::make_shared<io::TumTrajectory>(io::TumTrajectory::load(options_.poses));
    countScans();
    open();
}

ReplaySession::~ReplaySession() = default;

void ReplaySession::countScans() {
    io::RawlogSourceParams sp;
    sp.sensor_label = params_.sensor.label_filter;
    io::RawlogScanSource source(options_.rawlog, sp,
                                poses_ ? std::optional<io::TumTrajectory>(*poses_) : std::nullopt);
    try {
        while (auto scan = source.next()) stamps_.push_back(scan->stamp_s);
    } catch (const std::runtime_error& e) {
        damage_ = e.what();  // the scans before the damage are replayed, as `stairmap map` does
    }
}

void ReplaySession::open() {
    io::RawlogSourceParams sp;
    sp.sensor_label = params_.sensor.label_filter;
    source_ = std::make_unique<io::RawlogScanSource>(
        options_.rawlog, sp, poses_ ? std::optional<io::TumTrajectory>(*poses_) : std::nullopt);
    LandmarkMap landmarks = options_.map_in.empty()
                                ? LandmarkMap(params_.landmarks)
                                : io::loadLandmarkMap(options_.map_in, params_.landmarks);
    mapper_ = std::make_unique<pipeline::Mapper>(params_, std::move(landmarks));
    mapper_->setDetectionRunCallback([this](const pipeline::DetectionRun& r) { onRun(r); },
                                     options_.with_debug);
    position_ = 0;
    runs_ = 0;
    last_scan_.reset();
    last_run_.reset();
}

void ReplaySession::onRun(const pipeline::DetectionRun& run) {
    RunSnapshot snap;
    snap.scan_index = run.scan_index;
    snap.stamp_s = run.stamp_s;
    snap.T_world_grav = run.T_world_grav;
    snap.submap_radius_m = run.submap_radius_m;
    snap.submap_points = run.submap ? run.submap->size() : 0;
    snap.detect_ms = 1000.0 * run.detect_s;
    if (run.debug) snap.debug = *run.debug;
    snap.records = run.records;
    last_run_ = std::move(snap);
    ++runs_;
}

bool ReplaySession::advance() {
    if (position_ >= stamps_.size()) return false;
    std::optional<Scan> scan;
    try {
        scan = source_->next();
    } catch (const std::runtime_error&) {
        return false;  // damage_ already holds the message from the first pass
    }
    if (!scan) return false;
    mapper_->processScan(*scan);
    last_scan_ = std::move(scan);
    ++position_;
    return true;
}

void ReplaySession::seek(std::size_t n) {
    n = std::min(n, stamps_.size());
    if (n < position_) open();
    while (position_ < n && advance()) {
    }
}

void ReplaySession::restart() { open(); }

}  // namespace stairmap::replay
