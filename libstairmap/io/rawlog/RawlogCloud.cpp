// Reading one 3D cloud from an MRPT rawlog (format #1 action/sensory-frame pairs or format #2
// observations, plain or gzipped). The FIRST observation that converts to 3D points is used; later
// content is not read, so a rawlog holding a whole sequence gives its first scan.

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/rawlog/RawlogCloud.h"
#include "io/rawlog/ObservationToPoints.h"
#include "io/rawlog/GuardedReadObject.h"
#include "io/rawlog/RawlogScanSource.h"

namespace stairmap::io {

namespace {

/// The innermost "Message:" of an MRPT exception text (those nest and carry call traces), else
/// the first line; at most 200 characters.
std::string shortMessage(const std::string& text) {
    const std::size_t tag = text.rfind("Message:");
    std::size_t begin = tag == std::string::npos ? 0 : tag + 8;
    while (begin < text.size() && text[begin] == ' ') ++begin;
    const std::size_t end = text.find('\n', begin);
    return text.substr(begin, std::min<std::size_t>(end == std::string::npos ? text.size() - begin : end - begin, 200));
}

/// Converts `obs` if it is a 3D observation; std::nullopt otherwise.
std::optional<PointCloud> tryConvert(const mrpt::obs::CObservation& obs) {
    if (!isConvertible3DObservation(obs)) return std::nullopt;
    ObservationPoints converted = observationToRobotPoints(obs);
    if (converted.points_robot.empty() && converted.dropped_non_finite > 0) {
        throw std::runtime_error("contains no finite points (" + std::to_string(converted.dropped_non_finite) +
                                 " points in the first 3D observation, all NaN/Inf)");
    }
    return std::move(converted.points_robot);
}

std::optional<PointCloud> tryConvertObject(const mrpt::serialization::CSerializable::Ptr& object) {
    if (const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) return tryConvert(*obs);
    if (const auto frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
        for (const auto& obs : *frame) {
            if (!obs) continue;
            if (auto cloud = tryConvert(*obs)) return cloud;
        }
    }
    return std::nullopt;  // actions, poses, IMU, ... are skipped
}

}  // namespace

PointCloud readRawlogCloud(const std::string& path) {
    mrpt::io::CFileGZInputStream file;
    if (!file.open(path)) throw std::runtime_error(path + ": cannot be opened for reading");
    auto archive = mrpt::serialization::archiveFrom(file);
    std::size_t num_objects = 0;
    try {
        while (true) {
            const std::uint64_t position = file.getPosition();
            mrpt::serialization::CSerializable::Ptr object;
            try {
                object = guardedReadObject(archive, RawlogSourceParams{}.max_object_bytes);
            } catch (const mrpt::serialization::CExceptionEOF&) {
                if (file.getPosition() == position) break;  // clean end between two objects
                throw;
            }
            ++num_objects;
            if (auto cloud = tryConvertObject(object)) return std::move(*cloud);
        }
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": not a valid MRPT rawlog, or corrupt/truncated at object " +
                                 std::to_string(num_objects + 1) + " (" + shortMessage(e.what()) + ")");
    }
    throw std::runtime_error(path + ": no 3D observation (CObservationPointCloud, CObservationVelodyneScan or "
                                    "CObservation3DRangeScan) among its " + std::to_string(num_objects) + " objects");
}

}  // namespace stairmap::io
