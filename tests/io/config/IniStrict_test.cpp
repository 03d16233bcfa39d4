// Strict INI checking: malformed lines and unknown sections/keys are errors naming file, line and
// key (MRPT's CConfigFile would ignore them); every shipped INI file (configs, robot profiles,
// scenes) still loads.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/config/ConfigFile.h"
#include "io/config/IniKeys.h"
#include "io/config/IniSyntax.h"
#include "io/config/MapperConfig.h"
#include "io/config/RobotProfileConfig.h"
#include "io/config/SceneIni.h"

namespace stairmap::io {
namespace {

namespace fs = std::filesystem;

std::string writeIni(const std::string& name, const std::string& text) {
    // One folder per test: ctest -j runs these tests in parallel processes, and a shared
    // config.ini was overwritten by one test while another loaded it.
    const fs::path dir = fs::path(STAIRMAP_TEST_TMP) / "io_strict_ini" /
                         testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
}

/// Loads `text` as a stairmap config file and returns the error text ("" if none).
std::string configError(const std::string& text) {
    const std::string path = writeIni("config.ini", text);
    try {
        loadMapperParams(path);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

void expectContains(const std::string& text, std::initializer_list<std::string> needles) {
    EXPECT_FALSE(text.empty()) << "no error";
    for (const auto& n : needles)
        EXPECT_NE(text.find(n), std::string::npos) << n << " in: " << text;
}

TEST(IniStrict, EveryShippedConfigAndSceneLoads) {
    int configs = 0, scenes = 0;
    for (const auto& e : fs::directory_iterator(fs::path(STAIRMAP_SOURCE_DIR) / "config")) {
        if (e.path().extension() != ".ini") continue;
        SCOPED_TRACE(e.path().string());
        EXPECT_NO_THROW(loadMapperParams(e.path().string()));
        EXPECT_NO_THROW(loadDetectorConfigFile(e.path().string()));
        ++configs;
    }
    for (const auto& e : fs::directory_iterator(fs::path(STAIRMAP_SOURCE_DIR) / "config/scenes")) {
        SCOPED_TRACE(e.path().string());
        EXPECT_NO_THROW(loadSimulationConfig(e.path().string()));
        ++scenes;
    }
    for (const auto& e : fs::directory_iterator(fs::path(STAIRMAP_SOURCE_DIR) / "config/robots")) {
        SCOPED_TRACE(e.path().string());
        EXPECT_NO_THROW(loadRobotProfile(e.path().string()));
        ++configs;
    }
    EXPECT_GE(configs, 8);
    EXPECT_GE(scenes, 20);
}

TEST(IniStrict, MisspelledSectionNamesFileLineAndTheValidSections) {
    const std::string path = writeIni("config.ini", "");
    expectContains(
        configError("# comment\n[detectr]\nleaf_size_m = 0.02\n"),
        {path + ":2:", "[detectr]", "did you mean [detector]", "landmarks", "scheduling"});
}

TEST(IniStrict, UnknownKeyNamesFileLineKeyAndListsTheValidKeys) {
    const std::string path = writeIni("config.ini", "");
    const std::string error = configError("[detector]\nmax_range_m = 8\nleaf_sise_m = 0.02\n");
    expectContains(error, {path + ":3:", "[detector] leaf_sise_m", "did you mean leaf_size_m",
                           "valid keys of [detector]", "max_range_m", "min_step_height_m"});
    // The valid keys listed are those of the section, not of the others.
    EXPECT_EQ(error.find("resolution_m"), std::string::npos) << error;
    expectContains(configError("[map]\nresolution = 0.1\n"),
                   {":2:", "[map] resolution", "resolution_m", "insertion_mode"});
}

TEST(IniStrict, MalformedLinesNameFileLineAndKey) {
    const std::string path = writeIni("config.ini", "");
    expectContains(configError("detector]\nleaf_size_m = 0.02\n"), {path + ":1:", "'detector]'"});
    expectContains(configError("[detector]\n\nleaf_size_m 0.02\n"),
                   {path + ":3:", "[detector] leaf_size_m", "no '='"});
    expectContains(configError("[detector\nleaf_size_m = 0.02\n"), {path + ":1:", "'[detector'"});
    expectContains(configError("leaf_size_m = 0.02\n[detector]\n"),
                   {path + ":1:", "before any [section]"});
    expectContains(configError("[detector]\nleaf size m = 0.02\n"), {path + ":2:", "leaf size m"});
    expectContains(configError("[detector] trailing\n"), {path + ":1:"});
}

TEST(IniStrict, WhatMrptAcceptsStaysAccepted) {
    // Comments of all three kinds, trailing // comments, blanks, case, @define and ${...}.
    EXPECT_EQ(configError("; c\n# c\n// c\n@define R 0.1\n[ Map ]  # c\n"
                          "  RESOLUTION_M = ${R} // trailing\n[detector] ; c\n"),
              "");
    EXPECT_DOUBLE_EQ(
        loadMapperParams(writeIni("define.ini", "@define R 0.1\n[map]\nresolution_m = ${R}\n"))
            .map.resolution_m,
        0.1);
}

TEST(IniStrict, TheKeyTableIsWhatTheLoadersRead) {
    const IniKeys& keys = configFileKeys();
    for (const char* section : {"sensor", "map", "scheduling", "detector", "landmarks", "floors"})
        EXPECT_EQ(keys.count(section), 1u) << section;
    // Each listed key is really read: a malformed value for it is an error naming it.
    for (const auto& [section, names] : keys) {
        for (const auto& key : names) {
            if (key == "label_filter") continue;  // free text: any value is valid
            const std::string error = configError("[" + section + "]\n" + key + " = not_a_value\n");
            EXPECT_NE(error.find(key), std::string::npos)
                << "[" << section << "] " << key << ": " << error;
        }
    }
}

TEST(IniStrict, SceneKeysDependOnTheSceneType) {
    const std::string head = "[scene]\ntype = ascending\n[clouds]\nposes = -2 0 0 0\n";
    const std::string path = writeIni("scene.ini", "");
    auto sceneError = [&](const std::string& text) -> std::string {
        writeIni("scene.ini", text);
        try {
            loadSimulationConfig(path);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(sceneError(head + "[stair]\nrise_m = 0.17\n"), "");
    expectContains(sceneError(head + "[stair]\nrise_m = 0.17\nrun = 0.3\n"),
                   {path + ":7:", "[stair] run", "did you mean run_m", "rise_m", "width_m"});
    // [spiral] is not read by an ascending scene.
    expectContains(sceneError(head + "[spiral]\nrise_m = 0.17\n"),
                   {path + ":5:", "[spiral]", "stair"});
    expectContains(sceneError(head + "[stair]\nrise_m 0.17\n"), {path + ":6:", "[stair] rise_m"});
}

TEST(IniSyntax, ReturnsSectionsAndKeysLowerCasedWithLineNumbers) {
    const auto lines = lexIni("# c\n[Detector]\nLeaf_Size_M = 1\n\n[map]\n", "x.ini");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0].line, 2);
    EXPECT_EQ(lines[0].section, "detector");
    EXPECT_EQ(lines[0].key, "");
    EXPECT_EQ(lines[1].line, 3);
    EXPECT_EQ(lines[1].key, "leaf_size_m");
    EXPECT_EQ(lines[2].section, "map");
}

TEST(IniKeys, RecorderSeesEveryKeyReadThroughIt) {
    mrpt::config::CConfigFileMemory cfg;
    cfg.setContent(std::string("[a]\nx = 1\n"));
    const KeyRecorder recorder(cfg);
    EXPECT_EQ(recorder.read_string("a", "x", ""), "1");
    EXPECT_EQ(recorder.read_string("B", "Y", "dflt"), "dflt");
    EXPECT_EQ(recorder.keys(), (IniKeys{{"a", {"x"}}, {"b", {"y"}}}));
}

}  // namespace
}  // namespace stairmap::io
