// Bad landmark files give a clear error naming the file and the problem and are never modified;
// a failed or interrupted save leaves the previous map intact.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>

#include "io/json/LandmarkJson.h"
#include "map/LandmarkTestMaps.h"

namespace stairmap {
namespace {

struct Corruption {
    const char* name;
    std::function<std::string(const std::string&)> mutate;  ///< good text -> bad text
    const char* expected;  ///< substring of the error message
};

std::string withJson(const std::string& good, const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json doc = nlohmann::json::parse(good);
    edit(doc);
    return doc.dump(2);
}

const std::vector<Corruption>& corruptions() {
    static const std::vector<Corruption> all = {
        {"Empty", [](const std::string&) { return std::string(); }, "not a valid JSON"},
        {"TruncatedHalf", [](const std::string& g) { return g.substr(0, g.size() / 2); },
         "truncated"},
        {"Garbage", [](const std::string&) { return std::string("\x01\x02 not json"); },
         "not a valid JSON"},
        {"WrongVersion",
         [](const std::string& g) { return withJson(g, [](auto& d) { d["version"] = 2; }); },
         "version: unsupported version 2"},
        {"WrongFrame",
         [](const std::string& g) { return withJson(g, [](auto& d) { d["frame"] = "odom"; }); },
         "frame"},
        {"MissingSteps",
         [](const std::string& g) {
             return withJson(g, [](auto& d) { d["staircases"][1].erase("steps"); });
         },
         "staircases[1].steps: missing"},
        {"BadPoint",
         [](const std::string& g) {
             return withJson(g, [](auto& d) { d["staircases"][0]["steps"][2]["end"] = {1, 2}; });
         },
         "staircases[0].steps[2].end: expected an array of 3 finite numbers"},
        {"WrongType",
         [](const std::string& g) {
             return withJson(g, [](auto& d) { d["staircases"][0]["observations"] = "many"; });
         },
         "staircases[0].observations: expected an integer"},
        {"NumStepsMismatch",
         [](const std::string& g) {
             return withJson(g, [](auto& d) { d["staircases"][0]["num_steps"] = 99; });
         },
         "num_steps: does not match"},
        {"DuplicateIds",
         [](const std::string& g) {
             return withJson(g, [](auto& d) { d["staircases"][1]["id"] = d["staircases"][0]["id"]; });
         },
         "duplicate staircase id"},
        {"BadParam",
         [](const std::string& g) {
             return withJson(g, [](auto& d) { d["params"]["landmarks"]["confirm_observations"] = -3; });
         },
         "confirm_observations"},
        {"MissingContinuation",
         [](const std::string& g) { return withJson(g, [](auto& d) { d.erase("continuation"); }); },
         "continuation: missing"},
    };
    return all;
}

class LandmarkFileCorrupt : public ::testing::TestWithParam<Corruption> {};

TEST_P(LandmarkFileCorrupt, ThrowsNamingFileAndProblemAndLeavesFileAlone) {
    const std::string dir = test::scratchDir(std::string("corrupt_") + GetParam().name);
    const std::string path = dir + "/landmarks.json";
    io::saveLandmarkMapAtomic(path, test::buildTestMap());
    const std::string bad = GetParam().mutate(test::readFile(path));
    test::writeFile(path, bad);
    try {
        io::loadLandmarkMap(path, LandmarkParams{});
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
        EXPECT_NE(what.find(GetParam().expected), std::string::npos) << what;
    }
    EXPECT_EQ(test::readFile(path), bad);
}

INSTANTIATE_TEST_SUITE_P(Files, LandmarkFileCorrupt, ::testing::ValuesIn(corruptions()),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

TEST(LandmarkFile, MissingFileNamesThePath) {
    const std::string path = test::scratchDir("missing") + "/nope.json";
    try {
        io::loadLandmarkMap(path);
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": cannot open", 0), 0u) << e.what();
    }
}

TEST(LandmarkFile, FailedSaveLeavesThePreviousMapAndNoTempFile) {
    const std::string dir = test::scratchDir("failed_save");
    const std::string path = dir + "/landmarks.json";
    LandmarkMap small;
    std::mt19937 rng(1);
    small.addDetection(test::makeDetection(test::FlightTruth{}, test::ViewSpec{}, rng), 0.0);
    io::saveLandmarkMapAtomic(path, small);
    const std::string before = test::readFile(path);
    // A folder that does not exist: the temp file cannot be created.
    EXPECT_THROW(io::saveLandmarkMapAtomic(dir + "/missing/landmarks.json", test::buildTestMap()),
                 std::runtime_error);
    EXPECT_EQ(test::readFile(path), before);
    // Renaming onto a directory fails after the temp file was written: it is cleaned up.
    const std::string dir_target = dir + "/a_directory";
    std::filesystem::create_directory(dir_target);
    std::filesystem::create_directory(dir_target + "/keep");
    EXPECT_THROW(io::saveLandmarkMapAtomic(dir_target, small), std::runtime_error);
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        (void)entry;
        ++files;
    }
    EXPECT_EQ(files, 2u);  // landmarks.json and a_directory, no leftover temp file
}

TEST(LandmarkFile, KillDuringRepeatedSavesAlwaysLeavesALoadableMap) {
    const std::string path = test::scratchDir("kill") + "/landmarks.json";
    const LandmarkMap map = test::buildTestMap();
    io::saveLandmarkMapAtomic(path, map);
    for (int round = 0; round < 8; ++round) {
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            for (;;) io::saveLandmarkMapAtomic(path, map);  // until killed
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(3 + 7 * round));
        ::kill(child, SIGKILL);
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status));
        const LandmarkMap loaded = io::loadLandmarkMap(path);  // throws on a partial file
        EXPECT_EQ(loaded.staircases().size(), map.staircases().size());
    }
    // Temp files left by the kills (unique names, io/system/AtomicFile.h) do not get in the way.
    io::saveLandmarkMapAtomic(path, map);
    EXPECT_EQ(io::loadLandmarkMap(path).staircases().size(), map.staircases().size());
}

}  // namespace
}  // namespace stairmap
