// `stairmap live --follow` against a writer PROCESS that appends the bundled two-floor rawlog (and
// its TUM poses, in step) in random-sized byte chunks at 10 Hz, flushing mid-object: the final
// landmarks must equal those of `stairmap map` on the finished log; SIGINT mid-run must leave
// outputs that --map-in resumes; bad input is reported, never a crash. Every child is waited for
// with a deadline (then killed), so the suite always ends.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "ChildProcess.h"
#include "CliRunner.h"

namespace stairmap::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using nlohmann::json;

const std::string kData = std::string(STAIRMAP_SOURCE_DIR) + "/datasets/two_floor/";
const std::string kRawlog = kData + "two_floor.rawlog";  // gzip; the writer appends it unpacked
const std::string kPoses = kData + "poses.tum";
const std::string kPreset = std::string(STAIRMAP_SOURCE_DIR) + "/config/sim_legged_vlp16.ini";
constexpr std::size_t kScansInLog = 83;

json loadJson(const std::string& path) { return json::parse(fileText(path)); }

/// Starts the chunk writer: SRC -> DST every period_ms in [min, max]-byte chunks (see
/// ChunkWriter.cpp); limit > 0 stops after that many bytes. Poses appended in step if given.
pid_t spawnWriter(const std::string& dst, int period_ms, int min_b, int max_b, int seed,
                  std::size_t limit = 0, const std::string& poses_dst = "") {
    const pid_t pid = ::fork();
    if (pid != 0) return pid;
    std::vector<std::string> args = {STAIRMAP_CHUNK_WRITER, kRawlog, dst, std::to_string(period_ms),
                                     std::to_string(min_b), std::to_string(max_b),
                                     std::to_string(seed), std::to_string(limit)};
    if (!poses_dst.empty()) {
        args.push_back(kPoses);
        args.push_back(poses_dst);
    }
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(STAIRMAP_CHUNK_WRITER, argv.data());
    ::_exit(127);
}

void touch(const std::string& path) { std::ofstream(path, std::ios::trunc).flush(); }

/// The reference: `stairmap map` on the finished log (once for the suite).
const json& referenceLandmarks() {
    static const json reference = [] {
        const std::string dir = cliScratchDir("live_follow", "reference");
        const CliResult r = runStairmap("map '" + kRawlog + "' --poses '" + kPoses + "' --config '" +
                                            kPreset + "' --out '" + dir + "/out' --quiet",
                                        dir);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return loadJson(dir + "/out/landmarks.json");
    }();
    return reference;
}

void expectPointNear(const json& a, const json& b, double tol, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i].get<double>(), b[i].get<double>(), tol) << what;
}

/// Same count, IDs, and geometry within 1 mm (every step's ends, rise, run, width, location).
void expectSameLandmarks(const json& got, const json& want) {
    ASSERT_EQ(got["staircases"].size(), want["staircases"].size());
    ASSERT_GE(want["staircases"].size(), 2u) << "the two-floor log has two flights";
    for (std::size_t i = 0; i < want["staircases"].size(); ++i) {
        const json& g = got["staircases"][i];
        const json& w = want["staircases"][i];
        const std::string id = "staircase " + std::to_string(i);
        EXPECT_EQ(g["id"], w["id"]) << id;
        EXPECT_EQ(g["num_steps"], w["num_steps"]) << id;
        EXPECT_EQ(g["observations"], w["observations"]) << id;
        for (const char* key : {"step_height", "step_depth", "step_width"})
            EXPECT_NEAR(g[key].get<double>(), w[key].get<double>(), 1e-3) << id << " " << key;
        expectPointNear(g["location"], w["location"], 1e-3, id + " location");
        ASSERT_EQ(g["steps"].size(), w["steps"].size()) << id;
        for (std::size_t k = 0; k < w["steps"].size(); ++k) {
            expectPointNear(g["steps"][k]["start"], w["steps"][k]["start"], 1e-3, id + " step start");
            expectPointNear(g["steps"][k]["end"], w["steps"][k]["end"], 1e-3, id + " step end");
        }
    }
    EXPECT_EQ(got["floors"].size(), want["floors"].size());
}

TEST(LiveFollow, WhileAWriterAppendsInRandomChunksTheLandmarksEqualThoseOfMap) {
    const json& want = referenceLandmarks();
    const std::string dir = cliScratchDir("live_follow", "equal_to_map");
    const std::string log = dir + "/growing.rawlog", poses = dir + "/growing.tum";
    touch(log);
    touch(poses);
    ChildOptions opts;
    opts.stderr_path = dir + "/stderr.txt";
    const pid_t live = spawnStairmap({"live", "--follow", log, "--poses", poses, "--config",
                                      kPreset, "--out", dir + "/out", "--idle-timeout", "2",
                                      "--quiet"}, opts);
    // 10 Hz, 60-260 kB chunks (~25 chunks): object boundaries fall anywhere inside chunks.
    const pid_t writer = spawnWriter(log, 100, 60000, 260000, 11, 0, poses);
    EXPECT_EQ(waitForExit(writer, 60s), 0);
    ASSERT_EQ(waitForExit(live, 60s), 0) << fileText(dir + "/stderr.txt");
    expectSameLandmarks(loadJson(dir + "/out/landmarks.json"), want);
    const json stats = loadJson(dir + "/out/stats.json");
    EXPECT_EQ(stats["live"]["scans_mapped"], kScansInLog);
    EXPECT_EQ(stats["live"]["dropped_scans"], 0);
    EXPECT_EQ(stats["live"]["ended"], "source ended");
    EXPECT_EQ(stats["live"]["source_counters"]["skipped_no_pose"], 0);
    EXPECT_GT(stats["live"]["latency"]["landmark_update"]["count"].get<int>(), 0);
    for (const char* f : {"map.bt", "scene.3Dscene", "overview.png"})
        EXPECT_GT(fs::file_size(dir + "/out/" + f), 0u) << f;
}

TEST(LiveFollow, SigintMidRunLeavesValidOutputsThatMapInResumes) {
    const std::string dir = cliScratchDir("live_follow", "sigint");
    const std::string log = dir + "/growing.rawlog";
    touch(log);
    ChildOptions opts;
    opts.stderr_path = dir + "/stderr.txt";
    opts.stdout_path = dir + "/stdout.txt";
    const pid_t live = spawnStairmap({"live", "--follow", log, "--poses", kPoses, "--config",
                                      kPreset, "--out", dir + "/out1", "--idle-timeout", "60",
                                      "--stats-every", "0.1"}, opts);
    // The writer stalls after 70 % of the log: the run is still going (waiting for growth).
    const pid_t writer = spawnWriter(log, 20, 50000, 200000, 3, 2650000);
    EXPECT_EQ(waitForExit(writer, 30s), 0);
    std::size_t mapped = 0;
    for (auto t0 = std::chrono::steady_clock::now(); std::chrono::steady_clock::now() - t0 < 30s;) {
        std::this_thread::sleep_for(100ms);
        try {
            mapped = loadJson(dir + "/out1/stats.json")["live"]["scans_mapped"].get<std::size_t>();
        } catch (const std::exception&) {  // not written yet
        }
        if (mapped >= 50) break;
    }
    ASSERT_GE(mapped, 50u) << fileText(dir + "/stderr.txt");
    // SIGUSR1: every output now, the run goes on.
    EXPECT_FALSE(fs::exists(dir + "/out1/map.bt"));
    ::kill(live, SIGUSR1);
    for (auto t0 = std::chrono::steady_clock::now();
         !fs::exists(dir + "/out1/overview.png") && std::chrono::steady_clock::now() - t0 < 10s;)
        std::this_thread::sleep_for(50ms);
    EXPECT_TRUE(fs::exists(dir + "/out1/map.bt"));
    EXPECT_TRUE(fs::exists(dir + "/out1/overview.png"));
    EXPECT_EQ(::waitpid(live, nullptr, WNOHANG), 0) << "a snapshot must not end the run";
    ::kill(live, SIGINT);
    ASSERT_EQ(waitForExit(live, 10s), 0) << fileText(dir + "/stderr.txt");
    const json stats = loadJson(dir + "/out1/stats.json");
    EXPECT_EQ(stats["live"]["ended"], "stopped by SIGINT");
    EXPECT_LT(stats["live"]["scans_mapped"].get<std::size_t>(), kScansInLog);
    const json partial = loadJson(dir + "/out1/landmarks.json");
    ASSERT_GE(partial["staircases"].size(), 1u);
    for (const char* f : {"map.bt", "scene.3Dscene", "overview.png"})
        EXPECT_GT(fs::file_size(dir + "/out1/" + f), 0u) << f;

    // Resume: the whole log again, continuing the stopped run's map: the landmarks it had keep
    // their IDs and places, and gain the new observations.
    const std::string full = dir + "/full.rawlog";
    ASSERT_EQ(waitForExit(spawnWriter(full, 0, 1 << 30, 1 << 30, 1), 30s), 0);
    const CliResult r = runStairmap("live --follow '" + full + "' --map-in '" + dir +
                                        "/out1/landmarks.json' --poses '" + kPoses + "' --config '" +
                                        kPreset + "' --out '" + dir + "/out2' --idle-timeout 0.3 --quiet",
                                    dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const json resumed = loadJson(dir + "/out2/landmarks.json");
    EXPECT_EQ(resumed["staircases"].size(), referenceLandmarks()["staircases"].size());
    for (const json& p : partial["staircases"]) {
        bool found = false;
        for (const json& q : resumed["staircases"]) {
            if (q["id"] != p["id"]) continue;
            found = true;
            expectPointNear(q["location"], p["location"], 0.3, "resumed location");
            EXPECT_GT(q["observations"].get<int>(), p["observations"].get<int>());
        }
        EXPECT_TRUE(found) << "landmark " << p["id"] << " lost its ID on resume";
    }
}

TEST(LiveFollow, MaxScansAndDurationEndARunEarlyWithEveryOutputWritten) {
    const std::string dir = cliScratchDir("live_follow", "limits");
    const std::string log = dir + "/full.rawlog";
    ASSERT_EQ(waitForExit(spawnWriter(log, 0, 1 << 30, 1 << 30, 1), 30s), 0);
    const std::string common = "live --follow '" + log + "' --poses '" + kPoses + "' --config '" +
                               kPreset + "' --quiet --idle-timeout 60 ";
    const CliResult a = runStairmap(common + "--max-scans 10 --out '" + dir + "/a'", dir);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const json sa = loadJson(dir + "/a/stats.json");
    EXPECT_EQ(sa["live"]["scans_mapped"], 10);
    EXPECT_EQ(sa["live"]["ended"], "--max-scans reached");
    // The whole file is read in well under a second; then the follower waits for growth that
    // never comes (idle timeout 60 s): --duration ends the run.
    const auto t0 = std::chrono::steady_clock::now();
    const CliResult b = runStairmap(common + "--duration 3 --out '" + dir + "/b'", dir);
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_LT(std::chrono::steady_clock::now() - t0, 20s);
    const json sb = loadJson(dir + "/b/stats.json");
    EXPECT_EQ(sb["live"]["ended"], "--duration reached");
    EXPECT_GT(sb["live"]["scans_mapped"].get<std::size_t>(), 0u);
    for (const char* f : {"landmarks.json", "map.bt", "scene.3Dscene", "overview.png"})
        EXPECT_TRUE(fs::exists(dir + "/b/" + f)) << f;
}

}  // namespace
}  // namespace stairmap::test
