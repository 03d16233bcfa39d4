#pragma once
// Test helpers for Velodyne decoding: a minimal pcap reader (Ethernet/IPv4/UDP), packet builders,
// independent counting of valid returns, and a nearest-neighbour lookup for cloud comparison.

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap::test {

/// UDP payloads of `payload_size` bytes sent to `port`, in capture order (little-endian pcap).
inline std::vector<std::vector<std::uint8_t>> readPcapUdpPayloads(const std::string& path,
                                                                  std::uint16_t port,
                                                                  std::size_t payload_size) {
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> d((std::istreambuf_iterator<char>(in)), {});
    auto u32 = [&](std::size_t o) { return d[o] | d[o + 1] << 8 | d[o + 2] << 16 | uint32_t(d[o + 3]) << 24; };
    auto be16 = [&](std::size_t o) { return std::uint16_t(d[o] << 8 | d[o + 1]); };
    if (d.size() < 24 || u32(0) != 0xa1b2c3d4u || u32(20) != 1) {
        throw std::runtime_error(path + ": not a little-endian Ethernet pcap");
    }
    std::vector<std::vector<std::uint8_t>> out;
    for (std::size_t off = 24; off + 16 <= d.size();) {
        const std::size_t len = u32(off + 8), pkt = off + 16;
        off = pkt + len;
        if (off > d.size() || len < 42 || be16(pkt + 12) != 0x0800) continue;  // IPv4 only
        const std::size_t ip_header = (d[pkt + 14] & 0x0F) * 4u, udp = pkt + 14 + ip_header;
        if (d[pkt + 14 + 9] != 17 || udp + 8 > off) continue;  // UDP only
        const std::size_t payload = udp + 8;
        if (be16(udp + 2) != port || off - payload != payload_size) continue;
        out.emplace_back(d.begin() + std::ptrdiff_t(payload), d.begin() + std::ptrdiff_t(off));
    }
    return out;
}

/// Counts returns with raw distance > 0 and range in [min, max], straight from the bytes.
inline std::size_t countValidReturns(const std::uint8_t* packet, double min_m, double max_m) {
    std::size_t n = 0;
    for (int block = 0; block < 12; ++block) {
        for (int ch = 0; ch < 32; ++ch) {
            const std::uint8_t* r = packet + block * 100 + 4 + 3 * ch;
            const int raw = r[0] | r[1] << 8;
            const double range = raw * 0.002;
            if (raw > 0 && range >= min_m && range <= max_m) ++n;
        }
    }
    return n;
}

/// Nearest-neighbour distance queries on a hashed 3D grid (exact within `max_query_m`).
class NearestNeighbour {
public:
    NearestNeighbour(const PointCloud& cloud, float cell_m) : cloud_(cloud), cell_(cell_m) {
        for (std::size_t i = 0; i < cloud.size(); ++i) grid_[key(cell(cloud[i]))].push_back(i);
    }
    /// Distance to the nearest point if within one cell, else +inf.
    float distance(const Eigen::Vector3f& q) const {
        const Eigen::Vector3i c = cell(q);
        float best = INFINITY;
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = grid_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
                    if (it == grid_.end()) continue;
                    for (std::size_t i : it->second) best = std::min(best, (cloud_[i] - q).norm());
                }
        return best <= cell_ ? best : INFINITY;
    }

private:
    Eigen::Vector3i cell(const Eigen::Vector3f& p) const {
        return (p / cell_).array().floor().cast<int>();
    }
    static std::int64_t key(const Eigen::Vector3i& c) {
        return (std::int64_t(c.x()) * 73856093) ^ (std::int64_t(c.y()) * 19349663) ^
               (std::int64_t(c.z()) * 83492791);
    }
    const PointCloud& cloud_;
    float cell_;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> grid_;
};

/// A 1206-byte packet: every block flagged, azimuth az0 + step * block [0.01 deg], all
/// distances zero, then return mode and product id.
inline std::vector<std::uint8_t> makeVelodynePacket(int az0, int step, std::uint8_t mode,
                                                    std::uint8_t product) {
    std::vector<std::uint8_t> p(1206, 0);
    for (int b = 0; b < 12; ++b) {
        const int az = (az0 + step * b) % 36000;
        p[b * 100] = 0xFF;
        p[b * 100 + 1] = 0xEE;
        p[b * 100 + 2] = std::uint8_t(az & 0xFF);
        p[b * 100 + 3] = std::uint8_t(az >> 8);
    }
    p[1204] = mode;
    p[1205] = product;
    return p;
}

inline void setReturn(std::vector<std::uint8_t>& p, int block, int channel, int raw_distance) {
    p[block * 100 + 4 + 3 * channel] = std::uint8_t(raw_distance & 0xFF);
    p[block * 100 + 5 + 3 * channel] = std::uint8_t(raw_distance >> 8);
    p[block * 100 + 6 + 3 * channel] = 100;  // reflectivity
}

}  // namespace stairmap::test
