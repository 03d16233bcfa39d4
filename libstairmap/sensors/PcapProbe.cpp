#include "sensors/PcapProbe.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace stairmap::sensors {
namespace {

constexpr std::size_t kVelodynePayload = 1206;  // [bytes] UDP payload of a data packet
constexpr std::uint32_t kMaxRecord = 1u << 18;   // [bytes] larger records are corrupt lengths

struct Format {
    bool swapped = false;      // file written on a machine of the other byte order
    double tick_s = 1e-6;      // [s] unit of the sub-second stamp field
};

std::uint32_t u32(const unsigned char* p, bool swapped) {
    const std::uint32_t le = p[0] | p[1] << 8 | p[2] << 16 | std::uint32_t(p[3]) << 24;
    const std::uint32_t be = p[3] | p[2] << 8 | p[1] << 16 | std::uint32_t(p[0]) << 24;
    return swapped ? be : le;
}

Format readGlobalHeader(std::istream& in, const std::string& path) {
    std::array<unsigned char, 24> h{};
    if (!in.read(reinterpret_cast<char*>(h.data()), h.size())) {
        throw std::runtime_error(path + ": not a pcap file (shorter than the 24-byte header)");
    }
    const std::uint32_t magic = u32(h.data(), false);
    Format f;
    if (magic == 0xa1b2c3d4u || magic == 0xa1b23c4du) {
        f.swapped = false;
    } else if (magic == 0xd4c3b2a1u || magic == 0x4d3cb2a1u) {
        f.swapped = true;
    } else {
        throw std::runtime_error(path + ": not a classic pcap file (bad magic number; pcapng is "
                                        "not supported, convert it with editcap -F pcap)");
    }
    const std::uint32_t m = u32(h.data(), f.swapped);
    f.tick_s = (m == 0xa1b23c4du) ? 1e-9 : 1e-6;
    const std::uint32_t link = u32(h.data() + 20, f.swapped);
    if (link != 1) {
        throw std::runtime_error(path + ": pcap link type " + std::to_string(link) +
                                 " is not Ethernet (1), which CVelodyneScanner expects");
    }
    return f;
}

/// True if the frame is IPv4/UDP to `port` with a Velodyne data payload.
bool isVelodyneData(const std::vector<unsigned char>& d, std::uint16_t port) {
    if (d.size() < 42 || d[12] != 0x08 || d[13] != 0x00) return false;  // not IPv4
    const std::size_t ip_header = (d[14] & 0x0F) * 4u;
    const std::size_t udp = 14 + ip_header;
    if (ip_header < 20 || d[14 + 9] != 17 || udp + 8 > d.size()) return false;  // not UDP
    const std::uint16_t dst = std::uint16_t(d[udp + 2] << 8 | d[udp + 3]);
    return dst == port && d.size() - (udp + 8) == kVelodynePayload;
}

}  // namespace

PcapSummary probePcap(const std::string& path, std::uint16_t data_port) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw std::runtime_error(path + (std::filesystem::exists(path, ec) ? ": not a file"
                                                                         : ": no such file"));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open for reading");
    const Format f = readGlobalHeader(in, path);
    PcapSummary s;
    std::array<unsigned char, 16> rh{};
    std::vector<unsigned char> frame;
    while (in.read(reinterpret_cast<char*>(rh.data()), rh.size())) {
        const std::uint32_t len = u32(rh.data() + 8, f.swapped);
        if (len > kMaxRecord) {  // a corrupt length: nothing after it can be trusted
            s.truncated = true;
            return s;
        }
        frame.resize(len);
        if (!in.read(reinterpret_cast<char*>(frame.data()), len)) {
            s.truncated = true;  // the file ends inside this record's data
            return s;
        }
        ++s.records;
        if (!isVelodyneData(frame, data_port)) {
            ++s.other_packets;
            continue;
        }
        const double t = u32(rh.data(), f.swapped) + u32(rh.data() + 4, f.swapped) * f.tick_s;
        if (s.data_packets++ == 0) s.first_data_s = t;
        s.last_data_s = t;
    }
    s.truncated = in.gcount() != 0;  // the file ends inside a record header
    return s;
}

}  // namespace stairmap::sensors
