#pragma once
// Our own decoder of Velodyne VLP-16 / HDL-32E data packets (the 1206-byte UDP payloads).
//
// Why: MRPT 2.5.8's CObservationVelodyneScan::generatePointCloud() decodes only part of each data
// block (see docs and tests/io/VelodyneDecoder_test.cpp). We decode ALL returns of every block:
//   VLP-16 : 12 blocks x 2 firing sequences x 16 lasers; the second sequence's azimuth is
//            interpolated halfway to the next block (timing per the VLP-16 manual: 2.304 us per
//            laser, 55.296 us per sequence). Dual-return packets (0x39) repeat each azimuth in
//            pairs of blocks; both returns are kept.
//   HDL-32E: 12 blocks x 32 lasers.
// Packet layout (little endian): per block 0xFFEE flag, azimuth [0.01 deg], 32 x (distance
// [2 mm], reflectivity); then a 4-byte timestamp, return mode, product id (0x21 HDL-32E,
// 0x22 VLP-16). A distance of 0 means "no return".
//
// Output frame (the "sensor frame", as MRPT's generatePointCloud): x at azimuth 0, y left, z up;
// the Velodyne azimuth grows clockwise seen from above, so y = -xy_range * sin(azimuth).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap::io {

enum class VelodyneModel { VLP16, HDL32 };

/// Per-laser geometry (the Velodyne calibration model): the beam's azimuth is
/// packet_azimuth - azimuth_correction_rad, its range is 2 mm * raw + distance_offset_m.
struct VelodyneLaser {
    double elevation_rad = 0.0;          ///< [rad] up positive
    double azimuth_correction_rad = 0.0; ///< [rad] subtracted from the packet azimuth
    double distance_offset_m = 0.0;      ///< [m] added to the measured range
    double vertical_offset_m = 0.0;      ///< [m] beam origin above the sensor origin
    double horizontal_offset_m = 0.0;    ///< [m] beam origin offset across the beam
};

/// Laser table of one sensor model, indexed by the laser's channel in the block.
struct VelodyneCalibrationTable {
    VelodyneModel model = VelodyneModel::VLP16;
    std::vector<VelodyneLaser> lasers;  ///< 16 (VLP-16) or 32 (HDL-32E)
};

/// Default tables from the public datasheets (VLP-16 manual table 9-1 incl. vertical offsets,
/// HDL-32E manual elevation list). No per-unit corrections.
VelodyneCalibrationTable defaultVelodyneCalibration(VelodyneModel model);

struct VelodyneDecoderParams {
    float min_range_m = 1.0f;    ///< [m] returns closer than this are dropped
    float max_range_m = 130.0f;  ///< [m] returns farther than this are dropped
};

/// Counts of one decode call.
struct VelodyneDecodeStats {
    std::size_t packets = 0;           ///< data packets decoded
    std::size_t bad_blocks = 0;        ///< blocks with an unknown flag (skipped)
    std::size_t valid_returns = 0;     ///< returns with distance > 0 in decoded blocks
    std::size_t range_filtered = 0;    ///< valid returns dropped by min/max range
};

constexpr std::size_t kVelodynePacketSize = 1206;  ///< [bytes] UDP payload of a data packet

/// Guesses the model from a packet's product id byte (0x21 HDL-32E, 0x22 VLP-16); otherwise
/// returns `fallback`.
VelodyneModel velodyneModelFromPacket(const std::uint8_t* packet, VelodyneModel fallback);

/// Decodes one 1206-byte data packet and APPENDS its points (sensor frame, metres) to `out`.
void decodeVelodynePacket(const std::uint8_t* packet, const VelodyneCalibrationTable& calib,
                          const VelodyneDecoderParams& params, PointCloud& out,
                          VelodyneDecodeStats& stats);

/// Decodes a sequence of packets (contiguous 1206-byte records) into a new cloud.
PointCloud decodeVelodynePackets(const std::uint8_t* packets, std::size_t num_packets,
                                 const VelodyneCalibrationTable& calib,
                                 const VelodyneDecoderParams& params,
                                 VelodyneDecodeStats* stats = nullptr);

}  // namespace stairmap::io
