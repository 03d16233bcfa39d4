// The pcap check run before MRPT's driver sees a capture.
#include <gtest/gtest.h>

#include "SensorTestUtil.h"
#include "io/rawlog/VelodyneTestUtil.h"
#include "sensors/PcapProbe.h"

using namespace stairmap;
using namespace stairmap::test;

TEST(PcapProbe, BundledCapture) {
    const auto s = sensors::probePcap(kPcap);
    EXPECT_EQ(s.data_packets, readPcapUdpPayloads(kPcap, 2368, 1206).size());
    EXPECT_EQ(s.data_packets, 293u);
    EXPECT_EQ(s.other_packets, 57u);  // GPS position packets
    EXPECT_FALSE(s.truncated);
    // 293 packets of a VLP-16 in single-return mode (754 packets/s): ~0.39 s of capture.
    EXPECT_NEAR(s.last_data_s - s.first_data_s, 292.0 / 754.0, 0.02);
}

TEST(PcapProbe, CutShortAndEmpty) {
    const std::string dir = tempDir("probe");
    const auto cut = sensors::probePcap(copyPrefix(kPcap, dir + "/cut.pcap", 200000));
    EXPECT_TRUE(cut.truncated);
    EXPECT_GT(cut.data_packets, 100u);
    EXPECT_LT(cut.data_packets, 293u);
    const auto header_only = sensors::probePcap(copyPrefix(kPcap, dir + "/h.pcap", 24));
    EXPECT_EQ(header_only.data_packets, 0u);
    EXPECT_FALSE(header_only.truncated);
    const auto cut_header = sensors::probePcap(copyPrefix(kPcap, dir + "/h2.pcap", 30));
    EXPECT_TRUE(cut_header.truncated);
    EXPECT_THROW(sensors::probePcap(copyPrefix(kPcap, dir + "/short.pcap", 10)), std::runtime_error);
    EXPECT_THROW(sensors::probePcap(dir + "/missing.pcap"), std::runtime_error);
    EXPECT_THROW(sensors::probePcap(dir), std::runtime_error);  // a folder
}

TEST(PcapProbe, RejectsOtherFormats) {
    const std::string dir = tempDir("probe_formats");
    std::string pcapng(64, '\0');
    pcapng[0] = 0x0a, pcapng[1] = 0x0d, pcapng[2] = 0x0d, pcapng[3] = 0x0a;
    EXPECT_THROW(sensors::probePcap(writeFile(dir + "/a.pcapng", pcapng)), std::runtime_error);
    std::string other_link = readFile(kPcap).substr(0, 24);
    other_link[20] = 113;  // Linux cooked capture
    try {
        sensors::probePcap(writeFile(dir + "/l.pcap", other_link));
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("not Ethernet"), std::string::npos) << e.what();
    }
}
