#pragma once
// A look at a pcap file before MRPT's CVelodyneScanner replays it. Why: the driver (MRPT 2.5.8,
// built with libpcap) spins for ever printing "Maybe the PCAP file is empty?" when a file holds no
// complete Velodyne packet, and says nothing when a file is cut short. Reading the file once
// first turns both into a clear error or a counted, reported condition.
// Format: classic pcap (not pcapng), either byte order, micro- or nanosecond stamps, Ethernet
// link layer, IPv4/UDP, as Velodyne captures (Wireshark, tcpdump, VeloView) are written.

#include <cstddef>
#include <cstdint>
#include <string>

namespace stairmap::sensors {

/// What a pcap file holds, as far as a Velodyne replay is concerned.
struct PcapSummary {
    std::size_t records = 0;         ///< complete packet records
    std::size_t data_packets = 0;    ///< UDP payloads of 1206 bytes to the data port
    std::size_t other_packets = 0;   ///< everything else (position packets, other traffic)
    bool truncated = false;          ///< the file ends inside a record (cut-off capture)
    double first_data_s = 0.0;       ///< [s] capture stamp of the first data packet
    double last_data_s = 0.0;        ///< [s] capture stamp of the last data packet
};

/// Reads the whole file once (streaming, constant memory). Throws std::runtime_error
/// "<path>: <problem>" if it is missing, unreadable, not a classic pcap or not Ethernet.
/// data_port: the Velodyne data UDP port (2368 unless reconfigured).
PcapSummary probePcap(const std::string& path, std::uint16_t data_port = 2368);

}  // namespace stairmap::sensors
