// Bad input for `--sensor`: every problem is a clear error naming the INI file and section (or the
// pose file), or is counted while the run goes on; never a crash or a hang.
#include <gtest/gtest.h>

#include <fstream>

#include "SensorTestUtil.h"
#include "sensors/SensorSource.h"

using namespace stairmap;
using namespace stairmap::test;

namespace {

sensors::SensorSourceOptions staticRobot() {
    sensors::SensorSourceOptions o;
    o.static_robot = true;
    return o;
}

/// The message of the std::runtime_error that opening `ini` throws ("" if none is thrown).
std::string openError(const std::string& ini, const sensors::SensorSourceOptions& options = staticRobot()) {
    try {
        sensors::makeSensorSource(ini, options);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

void expectMentions(const std::string& message, const std::vector<std::string>& parts) {
    for (const auto& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

std::map<std::string, std::size_t> runToEnd(const std::string& ini, CollectingSink& sink) {
    auto source = sensors::makeSensorSource(ini, staticRobot());
    std::atomic<bool> stop{false};
    source->run(sink, stop);
    return source->counters();
}

}  // namespace

TEST(SensorSourceBadInput, MissingIniFile) {
    const std::string ini = tempDir("missing_ini") + "/nope.ini";
    expectMentions(openError(ini), {ini, "no such file"});
}

TEST(SensorSourceBadInput, IniWithoutSensorSection) {
    const std::string ini = writeFile(tempDir("no_section") + "/s.ini", "[global]\nrawlog_prefix = x\n");
    expectMentions(openError(ini), {ini, "no sensor section"});
}

TEST(SensorSourceBadInput, SectionWithoutDriver) {
    const std::string ini = writeFile(tempDir("no_driver") + "/s.ini", "[LIDAR]\nmodel = VLP16\n");
    expectMentions(openError(ini), {ini, "[LIDAR]", "driver"});
}

TEST(SensorSourceBadInput, UnknownDriverClass) {
    const std::string ini =
        writeFile(tempDir("unknown_driver") + "/s.ini", "[CAM]\ndriver = CNoSuchSensor\nprocess_rate = 10\n");
    expectMentions(openError(ini), {ini, "[CAM]", "CNoSuchSensor", "not an MRPT sensor class"});
}

TEST(SensorSourceBadInput, DriverWithoutProcessRate) {
    const std::string ini = writeFile(tempDir("no_rate") + "/s.ini", "[IMU]\ndriver = CIMUXSens\n");
    expectMentions(openError(ini), {ini, "[IMU]", "process_rate"});
}

TEST(SensorSourceBadInput, UnknownVelodyneModel) {
    const std::string dir = tempDir("bad_model");
    std::string text = velodyneIni(kPcap, true);
    text.replace(text.find("model = VLP16"), 13, "model = VLP99");
    const std::string ini = writeFile(dir + "/s.ini", text);
    expectMentions(openError(ini), {ini, "[LIDAR]", "VLP99"});
}

TEST(SensorSourceBadInput, MissingPcap) {
    const std::string dir = tempDir("missing_pcap");
    const std::string ini = writeFile(dir + "/s.ini", velodyneIni(dir + "/gone.pcap", true));
    expectMentions(openError(ini), {ini, "[LIDAR]", dir + "/gone.pcap", "no such file"});
}

TEST(SensorSourceBadInput, NotAPcap) {
    const std::string dir = tempDir("not_pcap");
    const std::string pcap = writeFile(dir + "/junk.pcap", std::string(200, 'x'));
    const std::string ini = writeFile(dir + "/s.ini", velodyneIni(pcap, true));
    expectMentions(openError(ini), {ini, "[LIDAR]", pcap, "not a classic pcap"});
}

// The driver itself would print "Maybe the PCAP file is empty?" for ever on these two.
TEST(SensorSourceBadInput, PcapWithHeaderOnlyOrNoCompletePacket) {
    const std::string dir = tempDir("empty_pcap");
    for (std::size_t bytes : {24, 1000}) {
        const std::string pcap = copyPrefix(kPcap, dir + "/cut" + std::to_string(bytes) + ".pcap", bytes);
        const std::string ini = writeFile(dir + "/s.ini", velodyneIni(pcap, true));
        expectMentions(openError(ini), {ini, "[LIDAR]", pcap, "no complete Velodyne data packet"});
    }
}

TEST(SensorSourceBadInput, TruncatedPcapReplaysWhatItHoldsAndIsCounted) {
    const std::string dir = tempDir("truncated_pcap");
    // 200000 bytes: the first 51 packets (the partial rotation) and the next full rotation, then
    // the file ends inside a packet.
    const std::string pcap = copyPrefix(kPcap, dir + "/cut.pcap", 200000);
    CollectingSink sink;
    const auto counters = runToEnd(writeFile(dir + "/s.ini", velodyneIni(pcap, true)), sink);
    EXPECT_EQ(counters.at("pcap_truncated_files"), 1u);
    ASSERT_GE(sink.scans.size(), 1u);
    EXPECT_LE(sink.scans.size(), 2u);
    EXPECT_EQ(counters.at("scans_pushed"), sink.scans.size());
}

TEST(SensorSourceBadInput, CorruptPacketsAreCountedAsBadObservations) {
    const std::string dir = tempDir("corrupt_packets");
    // Zero every byte of every data packet's payload past the first block's azimuth: the rotations
    // still split (block 0's azimuth is kept) but no block has a valid flag, so no point decodes.
    std::string d = readFile(kPcap);
    std::size_t corrupted = 0;
    for (std::size_t off = 24; off + 16 <= d.size();) {
        const std::size_t len = std::uint8_t(d[off + 8]) | std::uint8_t(d[off + 9]) << 8;
        const std::size_t payload = off + 16 + 42;
        if (len == 1248) {
            std::fill(d.begin() + std::ptrdiff_t(payload + 4), d.begin() + std::ptrdiff_t(payload + 1200), '\0');
            ++corrupted;
        }
        off += 16 + len;
    }
    ASSERT_EQ(corrupted, 293u);
    const std::string pcap = writeFile(dir + "/zeroed.pcap", d);
    CollectingSink sink;
    const auto counters = runToEnd(writeFile(dir + "/s.ini", velodyneIni(pcap, true)), sink);
    EXPECT_EQ(sink.scans.size(), 0u);
    EXPECT_EQ(counters.at("scans"), 4u);
    EXPECT_EQ(counters.at("bad_observations"), 4u);
}

TEST(SensorSourceBadInput, TwoSensorPosesForOneSensor) {
    const std::string dir = tempDir("two_poses");
    const std::string ini = writeFile(dir + "/s.ini", velodyneIni(kPcap, true, "pose_z = 0.5\n"));
    auto options = staticRobot();
    options.T_robot_sensor = Eigen::Isometry3d(Eigen::Translation3d(0, 0, 1));
    expectMentions(openError(ini, options), {ini, "[LIDAR]", "pose"});
}

TEST(SensorSourceBadInput, NeedsExactlyOnePoseSource) {
    const std::string dir = tempDir("pose_source");
    const std::string ini = writeFile(dir + "/s.ini", velodyneIni(kPcap, true));
    sensors::SensorSourceOptions none;
    EXPECT_THROW(sensors::makeSensorSource(ini, none), std::invalid_argument);
    sensors::SensorSourceOptions both = staticRobot();
    both.poses_path = writeFile(dir + "/p.tum", "");
    EXPECT_THROW(sensors::makeSensorSource(ini, both), std::invalid_argument);
}

TEST(SensorSourceBadInput, MissingOrMalformedPoseFile) {
    const std::string dir = tempDir("pose_file");
    const std::string ini = writeFile(dir + "/s.ini", velodyneIni(kPcap, true));
    sensors::SensorSourceOptions o;
    o.poses_path = dir + "/none.tum";
    expectMentions(openError(ini, o), {dir + "/none.tum", "no such file"});
    o.poses_path = writeFile(dir + "/bad.tum", "# header\n1.0 0 0 0 0 0 0 1\n2.0 0 0 zero\n");
    expectMentions(openError(ini, o), {dir + "/bad.tum:3:", "8 numbers"});
}
