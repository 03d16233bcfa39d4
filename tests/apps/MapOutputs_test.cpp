// Outputs of `stairmap map` that survive signals and each other: SIGINT/SIGTERM write every output
// for the map so far and exit 128 + signal; a second run on the same --out is refused naming the
// first one's pid; SIGKILL at any moment never leaves a truncated output where a complete one
// stood; no temp file is left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "ChildProcess.h"
#include "CliRunner.h"
#include "MapOutputChecks.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/";
const std::string kPreset = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";

std::vector<std::string> mapArgs(const std::string& out) {
    return {"map",      kData + "two_floor.rawlog",
            "--poses",  kData + "poses.tum",
            "--config", kPreset,
            "--out",    out,
            "--quiet"};
}

/// Scans in the bundled log: one per pose of its trajectory (the simulator writes one per scan).
int twoFloorScans() {
    std::ifstream poses(kData + "poses.tum");
    int count = 0;
    for (std::string line; std::getline(poses, line);) count += !line.empty() && line[0] != '#';
    return count;
}

/// A run slowed to ~40 ms per scan, so that it is surely in progress when the test acts on it.
ChildOptions slowRun(const std::string& dir) {
    ChildOptions options;
    options.env = {"STAIRMAP_TEST_SCAN_DELAY_MS=40"};
    options.stderr_path = dir + "/stderr.txt";
    return options;
}

void expectEveryOutputCompleteAndNothingElse(const fs::path& out) {
    for (const auto& name : mapOutputNames()) EXPECT_EQ(outputProblem(out, name), "") << name;
    const std::set<std::string> expected(mapOutputNames().begin(), mapOutputNames().end());
    EXPECT_EQ(filesIn(out), expected) << "temp or lock files left behind";
}

class MapStopSignal : public ::testing::TestWithParam<int> {};

TEST_P(MapStopSignal, WritesEveryOutputForTheMapSoFarAndExits128PlusSignal) {
    const int signal = GetParam();
    const std::string dir = cliScratchDir("map_outputs", "signal" + std::to_string(signal));
    const std::string out = dir + "/out";
    std::vector<std::string> args = mapArgs(out);
    args.push_back("--progress");  // the first progress line says the replay has begun
    const ChildOptions options = slowRun(dir);
    const pid_t pid = spawnStairmap(args, options);
    ASSERT_TRUE(waitForOutput(options.stderr_path, 60s)) << "no progress output";
    ::kill(pid, signal);
    ASSERT_EQ(waitForExit(pid), 128 + signal) << fileText(options.stderr_path);
    expectEveryOutputCompleteAndNothingElse(out);
    const auto stats = nlohmann::json::parse(fileText(out + "/stats.json"));
    const int scans = stats["scans"].get<int>();
    EXPECT_GT(scans, 0);
    EXPECT_LT(scans, twoFloorScans()) << "the signal did not stop the run early";
    const std::string err = fileText(options.stderr_path);
    EXPECT_NE(err.find(signal == SIGINT ? "SIGINT" : "SIGTERM"), std::string::npos) << err;
    // The landmark map so far continues in a next run (--map-in), with the same IDs.
    const CliResult next = runStairmap(
        "map '" + kData + "two_floor.rawlog' --poses '" + kData + "poses.tum' --config '" +
            kPreset + "' --map-in '" + out + "/landmarks.json' --out '" + dir + "/next' --quiet",
        dir);
    EXPECT_EQ(next.exit_code, 0) << next.err;
}

INSTANTIATE_TEST_SUITE_P(Signals, MapStopSignal, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& param_info) {
                             return param_info.param == SIGINT ? "SIGINT" : "SIGTERM";
                         });

TEST(MapOutputs, SecondRunOnTheSameOutRefusesNamingTheFirstsPid) {
    const std::string dir = cliScratchDir("map_outputs", "lock");
    const std::string out = dir + "/out";
    const ChildOptions options = slowRun(dir);
    std::vector<std::string> args = mapArgs(out);
    args.push_back("--progress");
    const pid_t first = spawnStairmap(args, options);
    ASSERT_TRUE(waitForOutput(options.stderr_path, 60s));
    ChildOptions second_options;
    second_options.stderr_path = dir + "/second.txt";
    const int second = waitForExit(spawnStairmap(mapArgs(out), second_options));
    const std::string err = fileText(second_options.stderr_path);
    EXPECT_EQ(second, 2) << err;
    EXPECT_NE(err.find("pid " + std::to_string(first)), std::string::npos) << err;
    EXPECT_NE(err.find(out), std::string::npos) << err;
    ::kill(first, SIGTERM);
    EXPECT_EQ(waitForExit(first), 128 + SIGTERM) << fileText(options.stderr_path);
    expectEveryOutputCompleteAndNothingElse(out);  // the refused run touched nothing
    // With the folder free again, a run succeeds.
    EXPECT_EQ(waitForExit(spawnStairmap(mapArgs(out))), 0);
    expectEveryOutputCompleteAndNothingElse(out);
}

/// Identity of a file's current content: inode, size and modification time.
std::tuple<ino_t, off_t, long> fileState(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return {0, -1, 0};
    return {st.st_ino, st.st_size, st.st_mtim.tv_nsec + 1000000000L * (st.st_mtim.tv_sec % 1000)};
}

/// SIGKILLs `pid` the moment `path` changes (the most dangerous moment for an in-place writer:
/// the file was just opened and truncated); or lets it finish if the file never changes.
void killWhenChanged(pid_t pid, const std::string& path) {
    const auto before = fileState(path);
    int status = 0;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
        if (fileState(path) != before) {
            ::kill(pid, SIGKILL);
            break;
        }
        std::this_thread::sleep_for(100us);
    }
    waitForExit(pid);
}

TEST(MapOutputs, KillAtAnyMomentNeverLeavesATruncatedOutput) {
    const std::string dir = cliScratchDir("map_outputs", "kill");
    const std::string out = dir + "/out";
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_EQ(waitForExit(spawnStairmap(mapArgs(out))), 0);
    const auto full = std::chrono::steady_clock::now() - t0;
    expectEveryOutputCompleteAndNothingElse(out);
    // Kills at random moments of a whole run ...
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> moment(0.0, 1.0);
    for (int round = 0; round < 4; ++round) {
        const double at = moment(rng);
        SCOPED_TRACE("kill at " + std::to_string(at) + " of a run");
        const pid_t pid = spawnStairmap(mapArgs(out));
        std::this_thread::sleep_for(
            std::chrono::duration_cast<std::chrono::microseconds>(full * at));
        ::kill(pid, SIGKILL);
        waitForExit(pid);
        for (const auto& name : mapOutputNames()) EXPECT_EQ(outputProblem(out, name), "") << name;
    }
    // ... and the moment each output changes.
    for (const auto& changed : mapOutputNames()) {
        SCOPED_TRACE("kill when " + changed + " changes");
        killWhenChanged(spawnStairmap(mapArgs(out)), out + "/" + changed);
        for (const auto& name : mapOutputNames()) EXPECT_EQ(outputProblem(out, name), "") << name;
    }
    // The next run sweeps the temp files the killed ones left, and leaves none of its own.
    ASSERT_EQ(waitForExit(spawnStairmap(mapArgs(out))), 0);
    expectEveryOutputCompleteAndNothingElse(out);
}

}  // namespace
}  // namespace stairmap::test
