#include "io/follow/RawlogFollowSource.h"

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace stairmap::io {
namespace {

bool isClassNameChar(unsigned char c) {
    return std::isalnum(c) || c == '_' || c == ':' || c == '<' || c == '>' || c == ',';
}

// MRPT 2 writes an object as (0x80 | name length) + class name (older files: a uint32 length);
// only the bytes already written are checked.
bool startsLikeMrptObject(const std::string& head) {
    if (head.empty()) return true;
    const auto b0 = static_cast<unsigned char>(head[0]);
    std::size_t length = 0, start = 0;
    if (b0 & 0x80) {
        length = b0 & 0x7F;
        start = 1;
    } else {
        if (head.size() < 4) return true;
        length = static_cast<unsigned char>(head[0]) | static_cast<unsigned char>(head[1]) << 8 |
                 static_cast<unsigned char>(head[2]) << 16 |
                 static_cast<std::size_t>(static_cast<unsigned char>(head[3])) << 24;
        start = 4;
    }
    if (length == 0 || length > 120) return false;
    for (std::size_t i = start; i < head.size() && i < start + length; ++i) {
        if (!isClassNameChar(static_cast<unsigned char>(head[i]))) return false;
    }
    return true;
}

}  // namespace

void checkFollowableRawlog(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw std::runtime_error(path + ": no such file");
    if (!std::filesystem::is_regular_file(path, ec))
        throw std::runtime_error(path + ": not a regular file (only files can be followed)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open for reading");
    std::string head(128, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    if (head.size() >= 2 && static_cast<unsigned char>(head[0]) == 0x1f &&
        static_cast<unsigned char>(head[1]) == 0x8b) {
        throw std::runtime_error(path +
                                 ": gzip-compressed; only a plain rawlog can be followed while it "
                                 "is written (map the finished file with `stairmap map`)");
    }
    if (!startsLikeMrptObject(head))
        throw std::runtime_error(path + ": not an MRPT rawlog (it does not start with a "
                                        "serialized object)");
}

RawlogFollowSource::RawlogFollowSource(std::string path, RawlogFollowParams params)
    : path_(std::move(path)), params_(std::move(params)) {}

std::string RawlogFollowSource::describe() const { return "rawlog " + path_ + " (followed)"; }

RawlogScanSource::PoseLookup RawlogFollowSource::poseLookup(const std::atomic<bool>& stop) {
    if (params_.static_robot)
        return [](double) { return std::optional<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()); };
    if (params_.poses_path.empty()) return {};  // CObservationRobotPose / odometry in the rawlog
    GrowingTrajectoryParams p = params_.poses;
    p.tolerance_s = params_.rawlog.tum_tolerance_s;
    trajectory_ = std::make_unique<GrowingTrajectory>(params_.poses_path, p, stop);
    return [this](double t) { return trajectory_->poseAt(t); };
}

void RawlogFollowSource::snapshot(const RawlogScanSource& source, const GrowingFileStream& stream) {
    const RawlogSourceStats& s = source.stats();
    std::size_t unsupported = 0;
    for (const auto& [type, n] : s.unsupported) unsupported += n;
    std::map<std::string, std::size_t> c = {
        {"objects_read", s.objects_read},         {"scans_read", s.scans_read},
        {"scans_pushed", s.scans_emitted},        {"skipped_no_pose", s.skipped_no_pose},
        {"skipped_label", s.skipped_label},       {"conversion_failed", s.conversion_failed},
        {"robot_poses_read", s.robot_poses_read}, {"odometry_read", s.odometry_read},
        {"non_finite_dropped", s.non_finite_dropped}, {"unsupported", unsupported},
        {"bytes_read", stream.getPosition()},     {"bytes_behind", stream.bytesBehind()}};
    if (trajectory_) {
        c["tum_poses_read"] = trajectory_->posesRead();
        c["scans_waited_for_pose"] = trajectory_->waits();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    counters_ = std::move(c);
    messages_ = source.messages();
}

void RawlogFollowSource::fail(const std::string& error, const GrowingFileStream& stream) const {
    if (stream.end() == GrowingFileEnd::Shrank)
        throw std::runtime_error(path_ + ": the file got shorter while followed (truncated or "
                                         "replaced by its writer)");
    if (stream.end() == GrowingFileEnd::IdleTimeout)
        throw std::runtime_error(error + " (the file stopped growing inside this object)");
    throw std::runtime_error(error);
}

void RawlogFollowSource::run(live::ScanSink& sink, const std::atomic<bool>& stop) {
    auto stream = std::make_unique<GrowingFileStream>(path_, params_.file, stop);
    const GrowingFileStream& file = *stream;
    RawlogScanSource source(std::move(stream), path_, params_.rawlog, poseLookup(stop));
    if (params_.on_warning) source.setWarningHandler(params_.on_warning);
    for (;;) {
        std::optional<Scan> scan;
        try {
            scan = source.next();
        } catch (const std::runtime_error& e) {
            snapshot(source, file);
            if (stop.load()) return;  // a short read caused by the stop, not damage
            fail(e.what(), file);
        }
        snapshot(source, file);
        if (!scan) break;
        sink.push(std::move(*scan));
        if (stop.load()) return;
    }
    if (file.end() == GrowingFileEnd::Shrank) fail("", file);
}

std::map<std::string, std::size_t> RawlogFollowSource::counters() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return counters_;
}

std::vector<std::string> RawlogFollowSource::messages() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return messages_;
}

}  // namespace stairmap::io
