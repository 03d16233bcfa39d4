// `stairmap live` on bad input: errors before any output is touched exit 2 with one line naming
// the file; damage found while following exits 1 with the outputs written up to there; poses that
// never arrive are counted, not waited for forever. Each run ends by itself in bounded time.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "ChildProcess.h"
#include "CliRunner.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/";
const std::string kRawlog = kData + "two_floor.rawlog";  // gzip-compressed
const std::string kPoses = kData + "poses.tum";
const std::string kPreset = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

/// The first `bytes` of the unpacked two-floor log (all of it for 0), written by the test's
/// chunk writer program in one go.
std::string plainLog(const std::string& dir, std::size_t bytes = 0) {
    const std::string path = dir + "/plain.rawlog";
    const std::string cmd = std::string("'") + STAIRMAP_CHUNK_WRITER + "' '" + kRawlog + "' '" +
                            path + "' 0 1073741824 1073741824 1 " + std::to_string(bytes);
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return path;
}

void expectRejectedBeforeOutputs(const CliResult& r, const std::string& file,
                                 const std::string& out, const std::string& why) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << "nothing may be written for bad input";
}

std::string liveArgs(const std::string& follow, const std::string& out, const std::string& extra) {
    return "live --follow '" + follow + "' --out '" + out + "' --quiet --idle-timeout 0.3 " + extra;
}

TEST(LiveBadInput, MissingFileIsNamedAndNothingIsWritten) {
    const std::string dir = cliScratchDir("live_bad_input", "missing");
    const std::string out = dir + "/out", missing = dir + "/nope.rawlog";
    expectRejectedBeforeOutputs(runStairmap(liveArgs(missing, out, "--static-robot"), dir), missing,
                                out, "no such file");
}

TEST(LiveBadInput, AFileThatIsNotARawlogIsNamedAndNothingIsWritten) {
    const std::string dir = cliScratchDir("live_bad_input", "not_rawlog");
    const std::string out = dir + "/out", text = dir + "/notes.rawlog";
    std::ofstream(text) << "# this is a text file, not a rawlog\n1 2 3\n";
    expectRejectedBeforeOutputs(runStairmap(liveArgs(text, out, "--static-robot"), dir), text, out,
                                "not an MRPT rawlog");
}

TEST(LiveBadInput, AGzipRawlogCannotBeFollowed) {
    const std::string dir = cliScratchDir("live_bad_input", "gzip");
    const std::string out = dir + "/out";
    expectRejectedBeforeOutputs(runStairmap(liveArgs(kRawlog, out, "--static-robot"), dir), kRawlog,
                                out, "gzip");
}

TEST(LiveBadInput, NoSourceOptionIsAnError) {
    const std::string dir = cliScratchDir("live_bad_input", "no_source");
    const CliResult r = runStairmap("live --out '" + dir + "/out'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("--follow"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(LiveBadInput, GarbageAfterGoodObjectsExitsOneWithTheMapUpToThere) {
    const std::string dir = cliScratchDir("live_bad_input", "garbage_tail");
    const std::string log = plainLog(dir, 1500000);  // ~1/3 of the log, cut inside an object
    std::ofstream(log, std::ios::app) << std::string(4000, '\x5a');
    const std::string out = dir + "/out";
    const CliResult r = runStairmap(
        liveArgs(log, out, "--poses '" + kPoses + "' --config '" + kPreset + "'"), dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(log), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("corrupt"), std::string::npos) << r.err;
    const json stats = json::parse(fileText(out + "/stats.json"));
    EXPECT_GT(stats["live"]["scans_mapped"].get<int>(), 10);
    EXPECT_EQ(stats["live"]["ended"], "source failed");
    EXPECT_TRUE(fs::exists(out + "/landmarks.json"));
    EXPECT_TRUE(fs::exists(out + "/map.bt"));
}

TEST(LiveBadInput, PosesThatNeverArriveAreCountedAndTheRunEnds) {
    const std::string dir = cliScratchDir("live_bad_input", "no_poses");
    const std::string log = plainLog(dir), poses = dir + "/empty.tum", out = dir + "/out";
    std::ofstream(poses).flush();  // the SLAM system never writes a pose
    const auto t0 = std::chrono::steady_clock::now();
    const CliResult r = runStairmap(
        liveArgs(log, out, "--poses '" + poses + "' --pose-wait 0.5 --config '" + kPreset + "'"), dir);
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const json stats = json::parse(fileText(out + "/stats.json"));
    EXPECT_EQ(stats["live"]["scans_mapped"], 0);
    EXPECT_EQ(stats["live"]["source_counters"]["skipped_no_pose"], 83);
    EXPECT_NE(r.err.find("warning"), std::string::npos) << "a warning says scans were skipped: " << r.err;
}

TEST(LiveBadInput, AMalformedLineInTheGrowingPoseFileIsNamed) {
    const std::string dir = cliScratchDir("live_bad_input", "bad_poses");
    const std::string log = plainLog(dir), poses = dir + "/bad.tum", out = dir + "/out";
    std::ofstream(poses) << "1700000000.0 0 0 0 0 0 0 1\nnot a pose line\n";
    const CliResult r = runStairmap(
        liveArgs(log, out, "--poses '" + poses + "' --pose-wait 0.2 --config '" + kPreset + "'"), dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find(poses), std::string::npos) << r.err;
}

}  // namespace
}  // namespace stairmap::test
