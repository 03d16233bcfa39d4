#include "io/rawlog/RawlogScanSource.h"

#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CActionRobotMovement3D.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <deque>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "io/rawlog/GuardedReadObject.h"
#include "io/rawlog/MrptErrorText.h"
#include "io/rawlog/PoseConversion.h"
#include "io/rawlog/RobotPoseMatcher.h"

namespace stairmap::io {
namespace {

using mrpt::obs::CObservation;

double stampOf(const CObservation& obs) {
    if (obs.timestamp == INVALID_TIMESTAMP) return std::nan("");
    return mrpt::Clock::toDouble(obs.timestamp);
}

void checkReadable(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw std::runtime_error(path + ": no such file");
    if (!std::filesystem::is_regular_file(path, ec)) throw std::runtime_error(path + ": not a file");
    if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open for reading");
}

}  // namespace

struct RawlogScanSource::Impl {
    RawlogSourceParams params;
    RawlogScanSource::PoseLookup pose_lookup;  // preference 1 (a TUM trajectory) when set
    std::unique_ptr<mrpt::io::CStream> stream;
    mrpt::serialization::CArchive::UniquePtr archive;
    RobotPoseMatcher matcher;
    std::deque<Scan> ready;
    Eigen::Isometry3d T_world_odom = Eigen::Isometry3d::Identity();  // composed increments
    bool have_odometry = false;
    bool eof = false;
    std::optional<std::string> error;
    std::set<std::string> warned_types;
    bool warned_no_pose = false;

    explicit Impl(const RawlogSourceParams& p) : params(p), matcher({p.pose_tolerance_s}) {}
};

RawlogScanSource::RawlogScanSource(const std::string& path, const RawlogSourceParams& params,
                                   std::optional<TumTrajectory> trajectory)
    : path_(path), impl_(std::make_unique<Impl>(params)) {
    checkReadable(path);
    if (trajectory) {
        const double tolerance_s = params.tum_tolerance_s;
        impl_->pose_lookup = [trajectory = std::move(*trajectory), tolerance_s](double t) {
            return trajectory.poseAt(t, tolerance_s);
        };
    }
    auto file = std::make_unique<mrpt::io::CFileGZInputStream>();
    try {
        if (!file->open(path)) throw std::runtime_error("open failed");
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": cannot open rawlog: " + mrptErrorText(e));
    }
    impl_->stream = std::move(file);
    impl_->archive = mrpt::serialization::archiveUniquePtrFrom(*impl_->stream);
}

RawlogScanSource::RawlogScanSource(std::unique_ptr<mrpt::io::CStream> stream,
                                   const std::string& name, const RawlogSourceParams& params,
                                   PoseLookup poses)
    : path_(name), impl_(std::make_unique<Impl>(params)) {
    if (!stream) throw std::invalid_argument(name + ": no stream to read");
    impl_->pose_lookup = std::move(poses);
    impl_->stream = std::move(stream);
    impl_->archive = mrpt::serialization::archiveUniquePtrFrom(*impl_->stream);
}

RawlogScanSource::~RawlogScanSource() = default;

void RawlogScanSource::setWarningHandler(std::function<void(const std::string&)> handler) {
    warning_handler_ = std::move(handler);
}

void RawlogScanSource::warn(const std::string& message) {
    messages_.push_back(path_ + ": " + message);
    if (warning_handler_) warning_handler_(messages_.back());
}

void RawlogScanSource::countUnsupported(const std::string& type_name, const std::string& reason) {
    ++stats_.unsupported[type_name];
    if (impl_->warned_types.insert(type_name).second) {
        warn(reason + " (counted in stats, reported once)");
    }
}

void RawlogScanSource::emit(Scan scan) {
    ++stats_.scans_emitted;
    stats_.points_emitted += scan.points_robot.size();
    impl_->ready.push_back(std::move(scan));
}

// One increment per action collection: the 3D movement if there is one, else the 2D odometry
// (logs often carry both for the same motion; composing both would count it twice).
void RawlogScanSource::handleActions(const mrpt::obs::CActionCollection& actions) {
    std::optional<mrpt::poses::CPose3D> increment_3d, increment_2d;
    for (const auto& action : actions) {
        if (const auto* a3 = dynamic_cast<const mrpt::obs::CActionRobotMovement3D*>(action.get())) {
            if (!increment_3d) increment_3d = a3->poseChange.mean;
        } else if (const auto* a2 =
                       dynamic_cast<const mrpt::obs::CActionRobotMovement2D*>(action.get())) {
            if (!increment_2d && a2->poseChange) {
                increment_2d = mrpt::poses::CPose3D(a2->poseChange->getMeanVal());
            }
        } else {
            const std::string type = action->GetRuntimeClass()->className;
            countUnsupported(type, "action type '" + type + "' is not used");
        }
    }
    const auto& increment = increment_3d ? increment_3d : increment_2d;
    if (!increment) return;
    if (!toIsometry(*increment).matrix().allFinite()) {
        countUnsupported("non-finite odometry", "a non-finite odometry increment was ignored");
        return;
    }
    impl_->T_world_odom = impl_->T_world_odom * toIsometry(*increment);
    impl_->have_odometry = true;
    ++stats_.odometry_read;
}

void RawlogScanSource::handleScan(const mrpt::obs::CObservation& obs, double stamp_s) {
    const std::size_t scan_index = stats_.scans_read++;
    ObservationPoints converted;
    try {  // e.g. an externally stored cloud whose file is missing: skip this scan, go on
        converted = observationToRobotPoints(obs, impl_->params.conversion);
    } catch (const std::exception& e) {
        converted.convertible = false;
        converted.type_name = obs.GetRuntimeClass()->className;
        converted.reason = mrptErrorText(e);
    }
    if (!converted.convertible) {
        ++stats_.conversion_failed;
        if (impl_->warned_types.insert("failed " + converted.type_name).second) {
            warn("scan index " + std::to_string(scan_index) + " (" + converted.type_name +
                 ") skipped: " + converted.reason + " (further failures only counted)");
        }
        return;
    }
    stats_.non_finite_dropped += converted.dropped_non_finite;
    Scan scan;
    scan.index = scan_index;
    scan.stamp_s = stamp_s;
    scan.sensor_label = obs.sensorLabel;
    scan.points_robot = std::move(converted.points_robot);
    if (impl_->pose_lookup) {  // preference 1: the TUM trajectory decides alone
        const auto T = impl_->pose_lookup(stamp_s);
        if (!T) {
            noteSkippedNoPose();
            return;
        }
        scan.T_world_robot = *T;
        emit(std::move(scan));
        return;
    }
    PendingScan pending{std::move(scan), std::nullopt};
    if (impl_->have_odometry) pending.fallback_T_world_robot = impl_->T_world_odom;
    impl_->matcher.addScan(std::move(pending));
}

void RawlogScanSource::handleObservation(const mrpt::obs::CObservation& obs) {
    const double stamp = stampOf(obs);
    impl_->matcher.observeStreamTime(stamp);
    if (const auto* rp = dynamic_cast<const mrpt::obs::CObservationRobotPose*>(&obs)) {
        ++stats_.robot_poses_read;
        const Eigen::Isometry3d T_world_robot = toIsometry(rp->pose.mean);
        if (T_world_robot.matrix().allFinite()) {
            impl_->matcher.addPose(stamp, T_world_robot);
        } else {
            countUnsupported("non-finite CObservationRobotPose",
                             "a CObservationRobotPose with non-finite values was ignored");
        }
        return;
    }
    if (!isConvertible3DObservation(obs)) {
        const std::string type = obs.GetRuntimeClass()->className;
        countUnsupported(type, "observation type '" + type + "' (label '" + obs.sensorLabel +
                                   "') cannot be converted to 3D points; ignored");
        return;
    }
    const std::string& wanted = impl_->params.sensor_label;
    if (!wanted.empty() && obs.sensorLabel != wanted) {
        ++stats_.skipped_label;
        return;
    }
    handleScan(obs, stamp);
}

void RawlogScanSource::handleObject(const mrpt::serialization::CSerializable::Ptr& object) {
    if (const auto* sf = dynamic_cast<const mrpt::obs::CSensoryFrame*>(object.get())) {
        for (const auto& obs : *sf) {
            if (obs) handleObservation(*obs);
        }
    } else if (const auto* obs = dynamic_cast<const CObservation*>(object.get())) {
        handleObservation(*obs);
    } else if (const auto* acts = dynamic_cast<const mrpt::obs::CActionCollection*>(object.get())) {
        handleActions(*acts);
    } else {
        const std::string type = object->GetRuntimeClass()->className;
        countUnsupported(type, "object type '" + type + "' is not a rawlog entry; ignored");
    }
}

void RawlogScanSource::readOneObject() {
    const uint64_t start = impl_->stream->getPosition();
    mrpt::serialization::CSerializable::Ptr object;
    try {
        object = guardedReadObject(*impl_->archive, impl_->params.max_object_bytes);
    } catch (const std::exception& e) {
        if (impl_->stream->getPosition() == start) {  // nothing of a new object: clean end
            impl_->eof = true;
            return;
        }
        impl_->error = path_ + ": truncated or corrupt at object index " +
                       std::to_string(stats_.objects_read) + " (scan index " +
                       std::to_string(stats_.scans_read) + "): " + mrptErrorText(e);
        return;
    }
    ++stats_.objects_read;
    if (object) handleObject(object);
}

void RawlogScanSource::drainMatcher(bool final) {
    for (;;) {
        RobotPoseMatcher::Resolution r = impl_->matcher.pop(final);
        if (!r.resolved) return;
        if (r.scan) {
            emit(std::move(*r.scan));
            continue;
        }
        noteSkippedNoPose();
    }
}

void RawlogScanSource::noteSkippedNoPose() {
    ++stats_.skipped_no_pose;
    if (!impl_->warned_no_pose) {
        impl_->warned_no_pose = true;
        warn(impl_->pose_lookup
                 ? "scan outside the TUM trajectory's time span skipped; further ones only counted"
                 : "scan without robot pose skipped (no CObservationRobotPose within tolerance, "
                   "no odometry); further ones only counted");
    }
}

std::optional<Scan> RawlogScanSource::next() {
    for (;;) {
        if (!impl_->ready.empty()) {
            Scan s = std::move(impl_->ready.front());
            impl_->ready.pop_front();
            return s;
        }
        const bool finished = impl_->eof || impl_->error.has_value();
        if (finished) {
            drainMatcher(true);
            if (!impl_->ready.empty()) continue;
            if (impl_->error) throw std::runtime_error(*impl_->error);
            return std::nullopt;
        }
        readOneObject();
        drainMatcher(false);
    }
}

}  // namespace stairmap::io
