#include "io/rawlog/VelodyneDecoder.h"

#include <cmath>
#include <cstring>

namespace stairmap::io {
namespace {

constexpr std::size_t kBlocksPerPacket = 12;
constexpr std::size_t kBlockSize = 100;             // [bytes] flag + azimuth + 32 returns
constexpr std::size_t kReturnsPerBlock = 32;
constexpr std::uint16_t kBlockFlag = 0xEEFF;        // bytes FF EE read little endian
constexpr std::uint8_t kDualReturnMode = 0x39;
constexpr double kDistanceUnit_m = 0.002;
constexpr double kDeg = M_PI / 180.0;

// VLP-16 manual: 2.304 us between lasers, 55.296 us per 16-laser firing sequence.
constexpr double kVlpLaserPeriod_us = 2.304;
constexpr double kVlpSequencePeriod_us = 55.296;
// HDL-32E manual: 1.152 us between lasers, 46.080 us per 32-laser firing.
constexpr double kHdlLaserPeriod_us = 1.152;
constexpr double kHdlFiringPeriod_us = 46.080;

std::uint16_t readU16(const std::uint8_t* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

std::uint16_t blockAzimuth(const std::uint8_t* packet, std::size_t block) {
    return readU16(packet + block * kBlockSize + 2);
}

// Azimuth advance [0.01 deg] between this block's firing and the next firing of the same
// return; the last block(s) of a packet reuse the previous advance.
double azimuthGap(const std::uint8_t* packet, std::size_t block, std::size_t stride) {
    std::size_t a = block, b = block + stride;
    if (b >= kBlocksPerPacket) {
        if (block < stride) return 0.0;
        a = block - stride;
        b = block;
    }
    const int gap = (int(blockAzimuth(packet, b)) - int(blockAzimuth(packet, a)) + 36000) % 36000;
    return gap > 1000 ? 0.0 : double(gap);  // > 10 deg between firings: not a real sweep
}

// Fraction of the azimuth gap elapsed when channel `channel` of the block fired.
double firingFraction(VelodyneModel model, std::size_t channel) {
    if (model == VelodyneModel::VLP16) {
        const std::size_t sequence = channel / 16, laser = channel % 16;
        return (sequence * kVlpSequencePeriod_us + laser * kVlpLaserPeriod_us) /
               (2.0 * kVlpSequencePeriod_us);
    }
    return channel * kHdlLaserPeriod_us / kHdlFiringPeriod_us;
}

Eigen::Vector3f beamPoint(const VelodyneLaser& laser, double range_m, double azimuth_rad) {
    const double rot = azimuth_rad - laser.azimuth_correction_rad;
    const double xy = range_m * std::cos(laser.elevation_rad);
    const double c = std::cos(rot), s = std::sin(rot);
    return {float(xy * c + laser.horizontal_offset_m * s),
            float(-xy * s + laser.horizontal_offset_m * c),
            float(range_m * std::sin(laser.elevation_rad) + laser.vertical_offset_m)};
}

}  // namespace

VelodyneCalibrationTable defaultVelodyneCalibration(VelodyneModel model) {
    VelodyneCalibrationTable table;
    table.model = model;
    if (model == VelodyneModel::VLP16) {
        // VLP-16 manual: laser id -> elevation [deg] and vertical offset [mm].
        const double elev[16] = {-15, 1, -13, 3, -11, 5, -9, 7, -7, 9, -5, 11, -3, 13, -1, 15};
        const double voff_mm[16] = {11.2, -0.7, 9.7, -2.2, 8.1, -3.7, 6.6, -5.1,
                                    5.1,  -6.6, 3.7, -8.1, 2.2, -9.7, 0.7, -11.2};
        for (int i = 0; i < 16; ++i) {
            VelodyneLaser l;
            l.elevation_rad = elev[i] * kDeg;
            l.vertical_offset_m = voff_mm[i] * 1e-3;
            table.lasers.push_back(l);
        }
    } else {
        const double elev[32] = {-30.67, -9.33,  -29.33, -8.00,  -28.00, -6.67, -26.67, -5.33,
                                 -25.33, -4.00,  -24.00, -2.67,  -22.67, -1.33, -21.33, 0.00,
                                 -20.00, 1.33,   -18.67, 2.67,   -17.33, 4.00,  -16.00, 5.33,
                                 -14.67, 6.67,   -13.33, 8.00,   -12.00, 9.33,  -10.67, 10.67};
        for (double e : elev) {
            VelodyneLaser l;
            l.elevation_rad = e * kDeg;
            table.lasers.push_back(l);
        }
    }
    return table;
}

VelodyneModel velodyneModelFromPacket(const std::uint8_t* packet, VelodyneModel fallback) {
    const std::uint8_t id = packet[kVelodynePacketSize - 1];
    if (id == 0x21) return VelodyneModel::HDL32;
    if (id == 0x22) return VelodyneModel::VLP16;
    return fallback;
}

void decodeVelodynePacket(const std::uint8_t* packet, const VelodyneCalibrationTable& calib,
                          const VelodyneDecoderParams& params, PointCloud& out,
                          VelodyneDecodeStats& stats) {
    const std::size_t num_lasers = calib.lasers.size();
    if (num_lasers == 0) return;
    const bool dual = packet[kVelodynePacketSize - 2] == kDualReturnMode;
    const std::size_t stride = dual ? 2 : 1;
    ++stats.packets;
    for (std::size_t block = 0; block < kBlocksPerPacket; ++block) {
        const std::uint8_t* b = packet + block * kBlockSize;
        if (readU16(b) != kBlockFlag) {
            ++stats.bad_blocks;
            continue;
        }
        const double azimuth = blockAzimuth(packet, block);
        const double gap = azimuthGap(packet, block, stride);
        for (std::size_t ch = 0; ch < kReturnsPerBlock; ++ch) {
            const std::uint16_t raw = readU16(b + 4 + 3 * ch);
            if (raw == 0) continue;
            ++stats.valid_returns;
            const VelodyneLaser& laser = calib.lasers[ch % num_lasers];
            const double range = raw * kDistanceUnit_m + laser.distance_offset_m;
            if (range < params.min_range_m || range > params.max_range_m) {
                ++stats.range_filtered;
                continue;
            }
            const double az = (azimuth + gap * firingFraction(calib.model, ch)) * 0.01 * kDeg;
            out.push_back(beamPoint(laser, range, az));
        }
    }
}

PointCloud decodeVelodynePackets(const std::uint8_t* packets, std::size_t num_packets,
                                 const VelodyneCalibrationTable& calib,
                                 const VelodyneDecoderParams& params, VelodyneDecodeStats* stats) {
    PointCloud out;
    out.reserve(num_packets * kBlocksPerPacket * kReturnsPerBlock);
    VelodyneDecodeStats local;
    for (std::size_t i = 0; i < num_packets; ++i) {
        decodeVelodynePacket(packets + i * kVelodynePacketSize, calib, params, out, local);
    }
    if (stats) *stats = local;
    return out;
}

}  // namespace stairmap::io
