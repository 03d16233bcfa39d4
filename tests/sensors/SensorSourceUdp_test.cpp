// `--sensor` on live UDP: the capture's data packets are sent to 127.0.0.1 on a free port, at the
// VLP-16's packet rate, and CVelodyneScanner (no pcap_input) receives them. The scans must be the
// rotations the pcap replay gives. Traffic stays on the loopback interface.
#include <gtest/gtest.h>
#include <mrpt/hwdrivers/CVelodyneScanner.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <thread>

#include "SensorTestUtil.h"
#include "io/rawlog/VelodyneTestUtil.h"
#include "sensors/SensorSource.h"

using namespace stairmap;
using namespace stairmap::test;
using mrpt::hwdrivers::CVelodyneScanner;

namespace {

sockaddr_in loopback(std::uint16_t port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return a;
}

/// A UDP port nobody uses right now (bound on 127.0.0.1 by the kernel, then released).
std::uint16_t freeUdpPort() {
    const int fd = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a = loopback(0);
    socklen_t len = sizeof(a);
    EXPECT_EQ(bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof(a)), 0);
    EXPECT_EQ(getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len), 0);
    close(fd);
    return ntohs(a.sin_port);
}

/// Restores the driver's (static, process-wide) UDP ports when the test ends.
struct PortOverride {
    short data = CVelodyneScanner::VELODYNE_DATA_UDP_PORT;
    short position = CVelodyneScanner::VELODYNE_POSITION_UDP_PORT;
    ~PortOverride() {
        CVelodyneScanner::VELODYNE_DATA_UDP_PORT = data;
        CVelodyneScanner::VELODYNE_POSITION_UDP_PORT = position;
    }
};

}  // namespace

TEST(SensorSourceUdp, PacketsOnLoopbackGiveThePcapRotations) {
    const PortOverride restore;
    const std::uint16_t port = freeUdpPort();
    CVelodyneScanner::VELODYNE_DATA_UDP_PORT = short(port);
    CVelodyneScanner::VELODYNE_POSITION_UDP_PORT = short(freeUdpPort());
    const std::string ini = writeFile(tempDir("udp") + "/live.ini",
                                      "[LIDAR]\ndriver = CVelodyneScanner\nprocess_rate = 1000\n"
                                      "sensorLabel = lidar\nmodel = VLP16\ndevice_ip = 127.0.0.1\n");
    sensors::SensorSourceOptions options;
    options.static_robot = true;
    auto source = sensors::makeSensorSource(ini, options);  // binds the sockets
    EXPECT_NE(source->describe().find("live UDP port " + std::to_string(port)), std::string::npos);

    CollectingSink sink;
    std::atomic<bool> stop{false};
    std::thread runner([&] { source->run(sink, stop); });
    const auto packets = readPcapUdpPayloads(kPcap, 2368, 1206);
    const int fd = socket(AF_INET, SOCK_DGRAM, 0);
    const sockaddr_in to = loopback(port);
    for (const auto& p : packets) {  // 754 packets/s, a VLP-16's rate in single-return mode
        sendto(fd, p.data(), p.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof(to));
        std::this_thread::sleep_for(std::chrono::microseconds(1326));
    }
    close(fd);
    for (int i = 0; i < 100 && sink.scans.size() < 4; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    stop = true;
    runner.join();

    // The rotations, split where block 0's azimuth goes down; the last one never completes.
    std::vector<std::size_t> valid(1, 0);
    int last_azimuth = -1;
    for (const auto& p : packets) {
        const int azimuth = p[2] | p[3] << 8;
        if (azimuth < last_azimuth) valid.push_back(0);
        last_azimuth = azimuth;
        valid.back() += countValidReturns(p.data(), 1.0, 120.0);
    }
    valid.pop_back();
    ASSERT_EQ(sink.scans.size(), valid.size());
    for (std::size_t k = 0; k < valid.size(); ++k) EXPECT_EQ(sink.scans[k].points_robot.size(), valid[k]) << k;
    EXPECT_EQ(source->counters().at("driver_errors"), 0u);
}
