// `stairmap map` on a rawlog whose point count is damaged: MRPT would resize the point arrays
// to the damaged count (gigabytes) before reading. The per-object allocation cap must turn that
// into the documented error (exit 1: damaged rawlog after good scans) at a bounded peak RSS.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/rawlog/RawlogTestUtil.h"
#include "pipeline/CliRunner.h"
#include "pipeline/PeakRss.h"

namespace stairmap::testing {
namespace {

namespace fs = std::filesystem;
using mrpt::poses::CPose3D;

constexpr int kScans = 5;
constexpr std::uint32_t kPointsOfScan0 = 2000;  // scan i has kPointsOfScan0 + i points

// A ~120 KB rawlog: kScans pose + cloud pairs, the robot 0.1 m further each time.
void writeScans(const fs::path& path) {
    test::RawlogWriter w(path.string(), false);
    for (int i = 0; i < kScans; ++i) {
        std::vector<Eigen::Vector3f> pts;
        for (std::uint32_t k = 0; k < kPointsOfScan0 + i; ++k) {
            pts.emplace_back(1.0f + 0.001f * k, -1.0f + 0.001f * (k % 2000), -0.3f);
        }
        w << *test::makePoseObs(i, CPose3D(0.1 * i, 0, 0, 0, 0, 0));
        w << *test::makeCloudObs(i, CPose3D(), pts);
    }
}

// Overwrites the 4 bytes at the `nth` (0-based) occurrence of `pattern` with `value` (little
// endian); false if there are fewer occurrences.
bool patchUint32(const fs::path& path, const std::string& pattern, int nth, std::uint32_t value) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    in.close();
    std::size_t at = std::string::npos;
    for (int k = 0, from = 0; k <= nth; ++k, from = int(at) + 1) {
        at = bytes.find(pattern, std::size_t(from));
        if (at == std::string::npos) return false;
    }
    std::memcpy(&bytes[at], &value, 4);
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return true;
}

std::string uint32Bytes(std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }

struct Damage {
    const char* name;
    std::string pattern;  ///< bytes whose first 4 are overwritten, in scan 3
    std::uint32_t value;
};

// Both cases used to pass the old 4 GiB address-space guard and be zero-filled: 3.2 GB and
// 3.7 GB peak RSS, minutes each, before the error.
const Damage kDamages[] = {
    // The point count of scan 3 (stored just before its x array): 2^28 points, 1 GiB per axis.
    {"point_count", uint32Bytes(kPointsOfScan0 + 3), 0x10000000u},
    // The length of scan 3's sensor label "lidar": a 3.5 GiB string.
    {"label_length", uint32Bytes(5) + "lidar", 0xE0000000u},
};

void PrintTo(const Damage& damage, std::ostream* os) { *os << damage.name; }

class MapCorruptRawlog : public ::testing::TestWithParam<Damage> {};

TEST_P(MapCorruptRawlog, HugeSizeFieldIsACleanErrorWithin512MB) {
    const Damage& damage = GetParam();
    const fs::path dir = scratch(std::string("corrupt_") + damage.name);
    const fs::path rawlog = dir / "damaged.rawlog";
    writeScans(rawlog);
    ASSERT_LT(fs::file_size(rawlog), 200u * 1024);
    const int occurrence = damage.pattern.size() == 4 ? 0 : 3;  // the count is unique, "lidar" is not
    ASSERT_TRUE(patchUint32(rawlog, damage.pattern, occurrence, damage.value));

    const ChildRun run = runMeasured({STAIRMAP_BIN, "map", rawlog.string(), "--out", (dir / "out").string()},
                                     (dir / "map.log").string());
    const std::string log = readText(dir / "map.log");
    EXPECT_EQ(run.exit_code, 1) << log;  // damaged rawlog after good scans (README)
    EXPECT_NE(log.find(rawlog.string()), std::string::npos) << log;
    EXPECT_NE(log.find("scan index 3"), std::string::npos) << log;
    EXPECT_GT(run.peak_rss_kb, 0);
    EXPECT_LT(run.peak_rss_kb, 512 * 1024) << "peak RSS " << run.peak_rss_kb / 1024 << " MiB";
    EXPECT_TRUE(fs::exists(dir / "out/landmarks.json"));  // the map of the 3 good scans
}

INSTANTIATE_TEST_SUITE_P(Damages, MapCorruptRawlog, ::testing::ValuesIn(kDamages),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace stairmap::testing
