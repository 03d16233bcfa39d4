#include "io/rawlog/ObservationToPoints.h"

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>

#include <cmath>
#include <optional>

#include "io/rawlog/PoseConversion.h"
#include "io/rawlog/VelodyneDecoder.h"

namespace stairmap::io {
namespace {

using mrpt::obs::CObservation3DRangeScan;
using mrpt::obs::CObservationPointCloud;
using mrpt::obs::CObservationVelodyneScan;

static_assert(sizeof(CObservationVelodyneScan::TVelodyneRawPacket) == kVelodynePacketSize,
              "MRPT's packet struct must be the raw 1206-byte UDP payload");

// Appends T * p where finite (a corrupt sensor pose makes every point non-finite); counts the rest.
template <typename GetPoint>
void appendTransformed(std::size_t n, GetPoint get, const Eigen::Isometry3d& T,
                       ObservationPoints& out) {
    const Eigen::Isometry3f Tf = T.cast<float>();
    out.points_robot.reserve(out.points_robot.size() + n);
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3f p = Tf * get(i);  // non-finite input or pose -> non-finite p
        if (!p.allFinite()) {
            ++out.dropped_non_finite;
            continue;
        }
        out.points_robot.push_back(p);
    }
}

void appendPointsMap(const mrpt::maps::CPointsMap& map, const Eigen::Isometry3d& T,
                     ObservationPoints& out) {
    const auto& xs = map.getPointsBufferRef_x();
    const auto& ys = map.getPointsBufferRef_y();
    const auto& zs = map.getPointsBufferRef_z();
    appendTransformed(
        xs.size(), [&](std::size_t i) { return Eigen::Vector3f(xs[i], ys[i], zs[i]); }, T, out);
}

void convertPointCloud(const CObservationPointCloud& obs, ObservationPoints& out) {
    obs.load();  // externally stored clouds (no-op otherwise)
    if (!obs.pointcloud) return;  // an empty observation is a valid, empty scan
    appendPointsMap(*obs.pointcloud, toIsometry(obs.sensorPose), out);
}

// Laser table: the observation's own calibration if it matches the model, else the datasheet.
VelodyneCalibrationTable velodyneTable(const CObservationVelodyneScan& obs, VelodyneModel model) {
    VelodyneCalibrationTable table = defaultVelodyneCalibration(model);
    const auto& corr = obs.calibration.laser_corrections;
    if (corr.size() != table.lasers.size()) return table;
    for (std::size_t i = 0; i < corr.size(); ++i) {
        VelodyneLaser& l = table.lasers[i];
        l.elevation_rad = std::atan2(corr[i].sinVertCorrection, corr[i].cosVertCorrection);
        l.azimuth_correction_rad = corr[i].azimuthCorrection * M_PI / 180.0;
        l.distance_offset_m = corr[i].distanceCorrection;
        l.vertical_offset_m = corr[i].verticalOffsetCorrection;
        l.horizontal_offset_m = corr[i].horizontalOffsetCorrection;
    }
    return table;
}

// The packet's product id decides (0x21 HDL-32E, 0x22 VLP-16); packets without one (old
// firmware) are identified by the size of the observation's calibration table.
std::optional<VelodyneModel> velodyneModelOf(const CObservationVelodyneScan& obs) {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(obs.scan_packets.data());
    const std::uint8_t id = bytes[kVelodynePacketSize - 1];
    if (id == 0x21) return VelodyneModel::HDL32;
    if (id == 0x22) return VelodyneModel::VLP16;
    if (id != 0) return std::nullopt;
    const std::size_t lasers = obs.calibration.laser_corrections.size();
    if (lasers == 32) return VelodyneModel::HDL32;
    if (lasers == 16 || lasers == 0) return VelodyneModel::VLP16;
    return std::nullopt;
}

void convertVelodyne(const CObservationVelodyneScan& obs, const ObservationConversionParams& params,
                     ObservationPoints& out) {
    if (obs.scan_packets.empty()) return;
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(obs.scan_packets.data());
    const std::optional<VelodyneModel> model = velodyneModelOf(obs);
    if (!model) {
        out.convertible = false;
        out.reason = "Velodyne model with product id " +
                     std::to_string(int(bytes[kVelodynePacketSize - 1])) + " and " +
                     std::to_string(obs.calibration.laser_corrections.size()) +
                     " calibrated lasers is not supported (VLP-16 and HDL-32E are)";
        return;
    }
    VelodyneDecoderParams dec;
    dec.min_range_m = std::max<float>(params.velodyne_min_range_m, float(obs.minRange));
    dec.max_range_m = std::min<float>(params.velodyne_max_range_m, float(obs.maxRange));
    const PointCloud sensor_points =
        decodeVelodynePackets(bytes, obs.scan_packets.size(), velodyneTable(obs, *model), dec);
    appendTransformed(
        sensor_points.size(), [&](std::size_t i) { return sensor_points[i]; },
        toIsometry(obs.sensorPose), out);
}

void convertRangeScan(const CObservation3DRangeScan& obs, ObservationPoints& out) {
    if (!obs.hasRangeImage) return;
    auto& mutable_obs = const_cast<CObservation3DRangeScan&>(obs);  // unprojectInto is non-const
    mrpt::maps::CSimplePointsMap map;
    mrpt::obs::T3DPointsProjectionParams pp;
    pp.takeIntoAccountSensorPoseOnRobot = true;  // -> robot frame
    mutable_obs.unprojectInto(map, pp);
    appendPointsMap(map, Eigen::Isometry3d::Identity(), out);
}

}  // namespace

bool isConvertible3DObservation(const mrpt::obs::CObservation& obs) {
    return dynamic_cast<const CObservationPointCloud*>(&obs) ||
           dynamic_cast<const CObservationVelodyneScan*>(&obs) ||
           dynamic_cast<const CObservation3DRangeScan*>(&obs);
}

ObservationPoints observationToRobotPoints(const mrpt::obs::CObservation& obs,
                                           const ObservationConversionParams& params) {
    ObservationPoints out;
    out.type_name = obs.GetRuntimeClass()->className;
    out.convertible = true;
    if (const auto* pc = dynamic_cast<const CObservationPointCloud*>(&obs)) {
        convertPointCloud(*pc, out);
    } else if (const auto* velo = dynamic_cast<const CObservationVelodyneScan*>(&obs)) {
        convertVelodyne(*velo, params, out);
    } else if (const auto* range = dynamic_cast<const CObservation3DRangeScan*>(&obs)) {
        convertRangeScan(*range, out);
    } else {
        out.convertible = false;
        out.reason = "MRPT 2.5 observation type '" + out.type_name +
                     "' cannot be converted to 3D points by stairmap";
    }
    return out;
}

}  // namespace stairmap::io
