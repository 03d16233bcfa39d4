// `stairmap detect`: exit codes and one-line errors for bad input, and the stdout contract.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

#include "CliRunner.h"
#include "io/cloud/CloudFile.h"

namespace stairmap::test {
namespace {

using nlohmann::json;

void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

/// Expects exit 2, nothing on stdout, and exactly one stderr line naming `name` and `phrase`.
void expectCliError(const CliResult& r, const std::string& name, const std::string& phrase) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(r.out.empty()) << "stdout: " << r.out;
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr: " << r.err;
    EXPECT_EQ(r.err.back(), '\n');
    EXPECT_EQ(r.err.rfind("stairmap detect: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << "stderr should name " << name << ": " << r.err;
    EXPECT_NE(r.err.find(phrase), std::string::npos) << "stderr should say " << phrase << ": " << r.err;
}

/// A flat floor 0.6 m below the robot: a valid cloud without staircases.
std::string writeFloorCloud(const std::string& path) {
    PointCloud floor;
    for (int i = -40; i <= 40; ++i) {
        for (int j = -40; j <= 40; ++j) floor.emplace_back(0.05f * i, 0.05f * j, -0.6f);
    }
    io::writeCloudFile(path, floor);
    return path;
}

TEST(DetectCli, HelpExplainsFramesUnitsAndOutput) {
    const CliResult r = runStairmap("detect --help", cliScratchDir("DetectCli", "help"));
    EXPECT_EQ(r.exit_code, 0);
    for (const char* phrase : {"--robot-height", "--config", "x forward, y left, z up", "metres", "time_ms",
                               "\"staircases\"", ".pcd", ".ply", ".xyz", ".rawlog"}) {
        EXPECT_NE(r.out.find(phrase), std::string::npos) << "help should mention " << phrase;
    }
}

TEST(DetectCli, CloudWithoutStairsPrintsOneEmptyResult) {
    const std::string dir = cliScratchDir("DetectCli", "floor");
    const std::string cloud = writeFloorCloud(dir + "/floor.pcd");
    const CliResult r = runStairmap("detect '" + cloud + "' --robot-height 0.6", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    ASSERT_FALSE(r.out.empty());
    EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << "stdout must be one line: " << r.out;
    const json j = json::parse(r.out);  // throws on anything but exactly one JSON value
    ASSERT_TRUE(j.is_object());
    EXPECT_EQ(j.at("staircases"), json::array());
    ASSERT_TRUE(j.at("time_ms").is_number());
    EXPECT_GE(j.at("time_ms").get<double>(), 0.0);
    EXPECT_NEAR(j.at("floor_z").get<double>(), -0.6, 0.05);
    EXPECT_EQ(j.at("num_points"), 81 * 81);
}

TEST(DetectCli, BadFilesExitTwoWithOneLineNamingTheFile) {
    const std::string dir = cliScratchDir("DetectCli", "bad_files");
    expectCliError(runStairmap("detect '" + dir + "/missing.pcd'", dir), "missing.pcd", "does not exist");
    writeFile(dir + "/empty.ply", "");
    expectCliError(runStairmap("detect '" + dir + "/empty.ply'", dir), "empty.ply", "file is empty");
    writeFile(dir + "/bad.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 5\nPOINTS 5\n"
                                "DATA binary\nabc");
    expectCliError(runStairmap("detect '" + dir + "/bad.pcd'", dir), "bad.pcd", "truncated binary data");
    writeFile(dir + "/text.xyz", "1 2 3\n1 two 3\n");
    expectCliError(runStairmap("detect '" + dir + "/text.xyz'", dir), "text.xyz", "'two' is not a number");
    writeFile(dir + "/nan.xyz", "nan 0 0\n0 inf 0\n0 0 -inf\n");
    expectCliError(runStairmap("detect '" + dir + "/nan.xyz'", dir), "nan.xyz", "contains no finite points");
    writeFile(dir + "/cloud.las", "1 2 3\n");
    expectCliError(runStairmap("detect '" + dir + "/cloud.las'", dir), "cloud.las", "unknown point-cloud file");
    writeFile(dir + "/junk.rawlog", "not a rawlog");
    expectCliError(runStairmap("detect '" + dir + "/junk.rawlog'", dir), "junk.rawlog", "not a valid MRPT rawlog");
    writeFile(dir + "/notgz.pcd.gz", "VERSION 0.7\n");
    expectCliError(runStairmap("detect '" + dir + "/notgz.pcd.gz'", dir), "notgz.pcd.gz", "not gzip data");
    writeFile(dir + "/cut.pcd.gz", std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", 10));
    expectCliError(runStairmap("detect '" + dir + "/cut.pcd.gz'", dir), "cut.pcd.gz", "truncated gzip data");
    std::filesystem::create_directories(dir + "/adir.pcd");
    expectCliError(runStairmap("detect '" + dir + "/adir.pcd'", dir), "adir.pcd", "not a regular file");
}

TEST(DetectCli, BadRobotHeightExitsTwo) {
    const std::string dir = cliScratchDir("DetectCli", "bad_height");
    const std::string cloud = writeFloorCloud(dir + "/floor.ply");
    expectCliError(runStairmap("detect '" + cloud + "' --robot-height -0.5", dir), "--robot-height", "-0.5");
    expectCliError(runStairmap("detect '" + cloud + "' --robot-height nan", dir), "--robot-height", "finite");
    expectCliError(runStairmap("detect '" + cloud + "' --robot-height inf", dir), "--robot-height", "finite");
    const CliResult text = runStairmap("detect '" + cloud + "' --robot-height tall", dir);
    EXPECT_EQ(text.exit_code, 2);
    EXPECT_TRUE(text.out.empty());
    EXPECT_NE(text.err.find("--robot-height"), std::string::npos) << text.err;
}

TEST(DetectCli, UsageErrorsExitTwo) {
    const std::string dir = cliScratchDir("DetectCli", "usage");
    const std::string cloud = writeFloorCloud(dir + "/floor.xyz");
    for (const std::string& args : {std::string("detect"), "detect '" + cloud + "' --frobnicate", "detect '" + cloud + "' extra",
                                   "detect '" + cloud + "' --robot-height"}) {
        const CliResult r = runStairmap(args, dir);
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_TRUE(r.out.empty()) << args << ": " << r.out;
        EXPECT_FALSE(r.err.empty()) << args;
    }
}

TEST(DetectCli, BadConfigFilesExitTwoNamingTheFile) {
    const std::string dir = cliScratchDir("DetectCli", "bad_config");
    const std::string cloud = writeFloorCloud(dir + "/floor.pcd");
    expectCliError(runStairmap("detect '" + cloud + "' --config '" + dir + "/nope.ini'", dir), "nope.ini",
                   "does not exist");
    writeFile(dir + "/text.ini", "[detector]\nmin_step_height_m = low\n");
    expectCliError(runStairmap("detect '" + cloud + "' --config '" + dir + "/text.ini'", dir), "text.ini",
                   "min_step_height_m");
    writeFile(dir + "/range.ini", "[detector]\nmax_step_height_m = -3\n");
    expectCliError(runStairmap("detect '" + cloud + "' --config '" + dir + "/range.ini'", dir), "range.ini",
                   "max_step_height_m");
    writeFile(dir + "/height.ini", "[detector]\nrobot_height_m = -1\n");
    expectCliError(runStairmap("detect '" + cloud + "' --config '" + dir + "/height.ini'", dir), "height.ini",
                   "robot_height_m");
}

TEST(DetectCli, ConfigRobotHeightSetsTheFloorAndTheOptionOverridesIt) {
    const std::string dir = cliScratchDir("DetectCli", "config_height");
    const std::string cloud = writeFloorCloud(dir + "/floor.pcd");
    writeFile(dir + "/h.ini", "[detector]\nrobot_height_m = 0.6\n");
    const CliResult from_config = runStairmap("detect '" + cloud + "' --config '" + dir + "/h.ini'", dir);
    ASSERT_EQ(from_config.exit_code, 0) << from_config.err;
    const json a = json::parse(from_config.out);
    EXPECT_EQ(a.at("floor_estimated"), false);
    EXPECT_NEAR(a.at("floor_z").get<double>(), -0.6, 0.05);
    EXPECT_EQ(a.at("input").at("cloud"), cloud);
    EXPECT_EQ(a.at("input").at("config"), dir + "/h.ini");
    EXPECT_DOUBLE_EQ(a.at("input").at("robot_height_m").get<double>(), 0.6);
    const CliResult overridden =
        runStairmap("detect '" + cloud + "' --config '" + dir + "/h.ini' --robot-height 0.58", dir);
    ASSERT_EQ(overridden.exit_code, 0) << overridden.err;
    EXPECT_EQ(json::parse(overridden.out).at("floor_estimated"), false);
    const CliResult estimated = runStairmap("detect '" + cloud + "'", dir);
    ASSERT_EQ(estimated.exit_code, 0) << estimated.err;
    const json e = json::parse(estimated.out);
    EXPECT_EQ(e.at("floor_estimated"), true);
    EXPECT_TRUE(e.at("input").at("config").is_null());
    EXPECT_TRUE(e.at("input").at("robot_height_m").is_null());
}

}  // namespace
}  // namespace stairmap::test
