// `stairmap live --sensor F.ini`: MRPT's CVelodyneScanner replays the bundled VLP-16 capture at its
// recorded rate into the live mapper. Each run ends by itself (pcap_read_once = true).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "CliRunner.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kPcap = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/real/sample_velodyne_vlp16_gps.pcap";

std::string writeIni(const std::string& dir, const std::string& pcap, const std::string& driver = "CVelodyneScanner") {
    const std::string path = dir + "/vlp16.ini";
    std::ofstream(path) << "[global]\n[LIDAR]\ndriver = " << driver << "\nprocess_rate = 1000\nsensorLabel = lidar\n"
                        << "model = VLP16\npcap_input = " << pcap << "\npcap_read_once = true\n";
    return path;
}

}  // namespace

TEST(LiveSensor, ReplaysThePcapIntoTheMapperAndWritesEveryOutput) {
    const std::string dir = cliScratchDir("live_sensor", "pcap");
    const std::string out = dir + "/out";
    const CliResult r = runStairmap("live --sensor '" + writeIni(dir, kPcap) + "' --static-robot --out '" + out +
                                        "' --quiet --queue 8",
                                    dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name : {"landmarks.json", "map.bt", "scene.3Dscene", "overview.png", "stats.json"}) {
        EXPECT_TRUE(fs::exists(out + "/" + name)) << name;
    }
    const json stats = json::parse(readText(out + "/stats.json"));
    const json& live = stats.at("live");
    EXPECT_TRUE(live.at("lossy").get<bool>());
    EXPECT_NE(live.at("source").get<std::string>().find("CVelodyneScanner [LIDAR]"), std::string::npos);
    const json& counters = live.at("source_counters");
    EXPECT_EQ(counters.at("scans").get<int>(), 4);  // the capture's partial first and 3 full rotations
    EXPECT_EQ(counters.at("scans_pushed").get<int>(), 4);
    EXPECT_EQ(counters.at("bad_observations").get<int>(), 0);
    // Lossy: what was not mapped was dropped by the queue, and counted.
    EXPECT_EQ(live.at("scans_mapped").get<int>() + live.at("dropped_scans").get<int>(), 4);
    EXPECT_GE(live.at("scans_mapped").get<int>(), 1);
}

TEST(LiveSensor, BadSensorIniIsNamedAndNothingIsWritten) {
    const std::string dir = cliScratchDir("live_sensor", "bad");
    const std::string out = dir + "/out";
    const std::string ini = writeIni(dir, dir + "/missing.pcap");
    CliResult r = runStairmap("live --sensor '" + ini + "' --static-robot --out '" + out + "' --quiet", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(ini + " [LIDAR]"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("missing.pcap"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    r = runStairmap("live --sensor '" + writeIni(dir, kPcap, "CNoSuchDriver") + "' --static-robot --out '" + out +
                        "' --quiet",
                    dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("CNoSuchDriver"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}
}  // namespace stairmap::test
