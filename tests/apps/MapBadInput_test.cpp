// The error contract of the CLI: bad input exits 2 with one line naming its file, found before any
// output is touched (an existing map in --out stays byte for byte); INI mistakes name file, line
// and key; running out of memory names the input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "ChildProcess.h"
#include "CliRunner.h"
#include "MapOutputChecks.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;

const std::string kRawlog =
    std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/two_floor.rawlog";
const std::string kPoses = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/poses.tum";
const std::string kPreset = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

std::string mapArgs(const std::string& rawlog, const std::string& out,
                    const std::string& extra = "") {
    return "map '" + rawlog + "' --out '" + out + "' --quiet " + extra;
}

std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& name : filesIn(dir)) files[name] = fileText((dir / name).string());
    return files;
}

/// One line on stderr (plus nothing on stdout) that names `file`.
void expectOneLineNaming(const CliResult& r, const std::string& file) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(MapBadInput, NoScanToMapExitsTwoAndLeavesTheMapInOutByteForByte) {
    const std::string dir = cliScratchDir("map_bad_input", "no_scan");
    const std::string out = dir + "/out";
    const CliResult first = runStairmap(
        mapArgs(kRawlog, out, "--poses '" + kPoses + "' --config '" + kPreset + "'"), dir);
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const auto before = snapshot(out);
    ASSERT_EQ(before.size(), mapOutputNames().size());

    const std::string empty = dir + "/empty.rawlog";
    std::ofstream(empty).close();
    const std::string cut = dir + "/cut.rawlog";  // damaged inside its first objects
    ASSERT_EQ(std::system(("gzip -dc < '" + kRawlog + "' | head -c 300 > '" + cut + "'").c_str()),
              0);
    const std::string other_label = dir + "/label.ini";
    std::ofstream(other_label) << "[sensor]\nlabel_filter = no_such_sensor\n";
    const std::string readme = std::string(STAIRMAP_SOURCE_DIR) + "/README.md";
    for (const auto& [rawlog, extra] : std::vector<std::pair<std::string, std::string>>{
             {readme, ""}, {empty, ""}, {cut, ""}, {kRawlog, "--config '" + other_label + "'"}}) {
        SCOPED_TRACE(rawlog + " " + extra);
        const CliResult r = runStairmap(mapArgs(rawlog, out, extra), dir);
        expectOneLineNaming(r, rawlog);
        EXPECT_EQ(snapshot(out), before) << "the map in --out was touched";
    }
}

TEST(MapBadInput, IniMistakesNameFileLineKeyAndTheValidKeys) {
    const std::string dir = cliScratchDir("map_bad_input", "ini");
    struct Case {
        std::string text, line, needle;
    };
    for (const Case& c :
         {Case{"[detectr]\nleaf_size_m = 0.02\n", ":1:", "[detectr]"},
          Case{"detector]\nleaf_size_m = 0.02\n", ":1:", "detector]"},
          Case{"[detector]\nleaf_size_m 0.02\n", ":2:", "leaf_size_m"},
          Case{"[detector]\nmax_range_m = 9\nleaf_sise_m = 0.02\n", ":3:", "leaf_sise_m"}}) {
        SCOPED_TRACE(c.text);
        const std::string ini = dir + "/mistake.ini";
        std::ofstream(ini) << c.text;
        const CliResult r =
            runStairmap(mapArgs(kRawlog, dir + "/out", "--config '" + ini + "'"), dir);
        expectOneLineNaming(r, ini + c.line);
        EXPECT_NE(r.err.find(c.needle), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir + "/out")) << "outputs created for a bad config";
        const CliResult d =
            runStairmap("detect '" + std::string(STAIRMAP_SOURCE_DIR) +
                            "/datasets/clouds/ascending_0.pcd.gz' --config '" + ini + "'",
                        dir);
        expectOneLineNaming(d, ini + c.line);
    }
    // An unknown key lists the valid keys of its section.
    const CliResult r =
        runStairmap(mapArgs(kRawlog, dir + "/out", "--config '" + dir + "/mistake.ini'"), dir);
    for (const char* key : {"leaf_size_m", "max_range_m", "min_steps", "detect_descending"})
        EXPECT_NE(r.err.find(key), std::string::npos) << key << " not listed: " << r.err;
}

TEST(MapBadInput, DirectoriesAndWrongTypesNameTheFile) {
    const std::string dir = cliScratchDir("map_bad_input", "dirs");
    expectOneLineNaming(runStairmap(mapArgs(kRawlog, dir + "/out", "--map-in '" + dir + "'"), dir),
                        dir);
    EXPECT_FALSE(fs::exists(dir + "/out"));
    // A real map to score (the short ascending sequence), then ground truths that are no files.
    const std::string seq = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/sequences/ascending";
    const CliResult map = runStairmap(
        mapArgs(seq + "/seq_ascending.rawlog", dir + "/ok", "--poses '" + seq + "/poses.tum'"),
        dir);
    ASSERT_EQ(map.exit_code, 0) << map.err;
    const std::string landmarks = dir + "/landmarks.json";
    fs::copy_file(dir + "/ok/landmarks.json", landmarks);
    expectOneLineNaming(runStairmap("eval '" + landmarks + "' --gt '" + dir + "'", dir), dir);
    for (const std::string gt :
         {R"({"format": 3})", R"({"format": "stairmap-gt", "frame": 2})",
          R"({"format": "stairmap-gt", "floor_heights": [0], "staircases": {}})"}) {
        SCOPED_TRACE(gt);
        std::ofstream(dir + "/gt.json") << gt;
        expectOneLineNaming(runStairmap("eval '" + landmarks + "' --gt '" + dir + "/gt.json'", dir),
                            dir + "/gt.json");
    }
}

#if !defined( \
    __SANITIZE_ADDRESS__)  // ASan reserves terabytes of address space: RLIMIT_AS cannot apply
TEST(MapBadInput, OutOfMemoryIsOneLineNamingTheInput) {
    const std::string dir = cliScratchDir("map_bad_input", "memory");
    const std::string fine = dir + "/fine.ini";
    std::ofstream(fine) << "[map]\nresolution_m = 0.005\n";  // a voxel map of a few hundred MB
    int out_of_memory = 0;
    // The limit at which the program loads but the map does not fit depends on the libraries'
    // footprint: try a range, lowest first, until one run reports it; each run either finishes,
    // fails to load its libraries (127) or reports running out of memory.
    // (432-496: the binary links MRPT hwdrivers for `live --sensor`, which loads ~90 more
    // libraries, e.g. OpenCV and Qt; below ~400 MB it no longer loads.)
    for (long mb : {240, 272, 304, 336, 368, 432, 464, 496}) {
        if (out_of_memory > 0) break;
        SCOPED_TRACE(mb);
        ChildOptions options;
        options.address_space_mb = mb;
        options.stderr_path = dir + "/err.txt";
        const std::string out = dir + "/out" + std::to_string(mb);
        const int status = waitForExit(spawnStairmap(
            {"map", kRawlog, "--poses", kPoses, "--config", fine, "--out", out, "--quiet"},
            options));
        const std::string err = fileText(options.stderr_path);
        ASSERT_TRUE(status == 0 || status == 2 || status == 127) << status << " " << err;
        if (status != 2) continue;
        ++out_of_memory;
        EXPECT_NE(err.find("out of memory"), std::string::npos) << err;
        EXPECT_TRUE(err.find(kRawlog) != std::string::npos || err.find(out) != std::string::npos)
            << err;
        EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
        if (!fs::exists(out)) continue;
        for (const auto& name : filesIn(out)) {
            EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
        }
    }
    EXPECT_GT(out_of_memory, 0) << "no limit made the run run out of memory";
}
#endif

}  // namespace
}  // namespace stairmap::test
