// Robot profiles from INI files: the three presets load, their verdicts flip exactly at each of
// their limits, and bad files fail with one message naming the file and the key.
#include "io/config/RobotProfileConfig.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>

#include "export/Traversability.h"

namespace stairmap::io {
namespace {

using exporting::FlightGeometry;
using exporting::RobotProfile;
using exporting::Travel;

std::string preset(const std::string& name) {
    return std::string(STAIRMAP_SOURCE_DIR) + "/config/robots/" + name + ".ini";
}

std::string writeIni(const std::string& name, const std::string& text) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "robot_profiles";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << text;
    return path;
}

std::string loadError(const std::string& path) {
    try {
        loadRobotProfile(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(RobotProfileConfig, PresetsLoad) {
    const RobotProfile tracked = loadRobotProfile(preset("tracked"));
    EXPECT_EQ(tracked.name, "tracked");
    EXPECT_DOUBLE_EQ(tracked.max_rise_m, 0.20);
    EXPECT_DOUBLE_EQ(tracked.max_slope_deg, 35.0);
    const RobotProfile quadruped = loadRobotProfile(preset("quadruped"));
    EXPECT_EQ(quadruped.name, "quadruped");
    EXPECT_TRUE(quadruped.can_ascend && quadruped.can_descend);
    const RobotProfile scout = loadRobotProfile(preset("scout"));
    EXPECT_FALSE(scout.can_ascend);
    EXPECT_FALSE(scout.can_descend);
}

/// A flight comfortably inside every limit of p.
FlightGeometry inside(const RobotProfile& p) {
    FlightGeometry f;
    f.rise_m = 0.5 * p.max_rise_m;
    f.run_m = p.min_run_m + 0.1;
    f.width_m = p.min_width_m + 0.3;
    f.slope_deg = 0.5 * p.max_slope_deg;
    f.risers = f.max_risers_between_landings = 1;
    return f;
}

struct Limit {
    const char* reason_word;  ///< the word the refusal starts with or contains
    std::function<void(FlightGeometry&, const RobotProfile&, double)> set;  ///< at limit + step
    double step;  ///< towards the failing side
};

bool mentions(const exporting::Verdict& v, const std::string& word) {
    return std::any_of(v.reasons.begin(), v.reasons.end(),
                       [&](const std::string& r) { return r.find(word) != std::string::npos; });
}

TEST(RobotProfileConfig, PresetVerdictsFlipAtEachLimit) {
    const std::vector<Limit> limits = {
        {"rise ",
         [](FlightGeometry& f, const RobotProfile& p, double d) { f.rise_m = p.max_rise_m + d; },
         0.005},
        {"run ",
         [](FlightGeometry& f, const RobotProfile& p, double d) { f.run_m = p.min_run_m - d; },
         0.005},
        {"width ",
         [](FlightGeometry& f, const RobotProfile& p, double d) { f.width_m = p.min_width_m - d; },
         0.01},
        {"slope ",
         [](FlightGeometry& f, const RobotProfile& p, double d) {
             f.slope_deg = p.max_slope_deg + d;
         },
         0.1},
        {"without a landing",
         [](FlightGeometry& f, const RobotProfile& p, double d) {
             f.max_risers_between_landings = p.max_steps_without_landing + static_cast<int>(d);
         },
         1.0}};
    for (const std::string name : {"tracked", "quadruped", "scout"}) {
        const RobotProfile p = loadRobotProfile(preset(name));
        for (const Limit& l : limits) {
            if (std::string(l.reason_word) == "run " && p.min_run_m == 0.0) continue;  // no limit
            for (Travel t : {Travel::Up, Travel::Down}) {
                const bool allowed = t == Travel::Up ? p.can_ascend : p.can_descend;
                FlightGeometry at = inside(p), across = inside(p);
                l.set(at, p, 0.0);
                l.set(across, p, l.step);
                const auto v_at = exporting::judgeFlight(at, p, t);
                const auto v_across = exporting::judgeFlight(across, p, t);
                EXPECT_EQ(v_at.traversable, allowed) << name << " at " << l.reason_word;
                EXPECT_FALSE(mentions(v_at, l.reason_word)) << name << " at " << l.reason_word;
                EXPECT_FALSE(v_across.traversable) << name << " across " << l.reason_word;
                EXPECT_TRUE(mentions(v_across, l.reason_word))
                    << name << " across " << l.reason_word;
            }
        }
    }
}

TEST(RobotProfileConfig, BadFilesNameTheFileAndKey) {
    const std::string negative = writeIni("negative.ini", "[robot]\nmax_rise_m = -0.1\n");
    std::string e = loadError(negative);
    EXPECT_NE(e.find(negative), std::string::npos) << e;
    EXPECT_NE(e.find("[robot] max_rise_m"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;

    e = loadError(writeIni("typo.ini", "[robot]\nmax_rise = 0.2\n"));
    EXPECT_NE(e.find("max_rise: unknown key"), std::string::npos) << e;
    e = loadError(writeIni("nosection.ini", "[robots]\nmax_rise_m = 0.2\n"));
    EXPECT_NE(e.find("no [robot] section"), std::string::npos) << e;
    e = loadError(writeIni("text.ini", "[robot]\nclearance_m = wide\n"));
    EXPECT_NE(e.find("[robot] clearance_m"), std::string::npos) << e;
    e = loadError(writeIni("steps.ini", "[robot]\nmax_steps_without_landing = 0\n"));
    EXPECT_NE(e.find("max_steps_without_landing"), std::string::npos) << e;
    e = loadError("/nonexistent/robot.ini");
    EXPECT_NE(e.find("/nonexistent/robot.ini"), std::string::npos) << e;
}

TEST(RobotProfileConfig, NameDefaultsToTheFileStem) {
    EXPECT_EQ(loadRobotProfile(writeIni("my_bot.ini", "[robot]\nmax_rise_m = 0.15\n")).name,
              "my_bot");
}

}  // namespace
}  // namespace stairmap::io
