// [landmarks]/[floors] INI loading: defaults in sync with config/default.ini, overrides, and
// invalid values naming the key.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include "io/config/IniFile.h"
#include "io/config/LandmarkConfig.h"
#include "map/LandmarkParamsFields.h"

namespace stairmap {
namespace {

TEST(LandmarkConfig, DefaultIniDocumentsEveryKeyWithTheBuiltInDefault) {
    const auto ini = io::openIniFile(std::string(STAIRMAP_SOURCE_DIR) + "/config/default.ini");
    const LandmarkParams loaded = io::loadLandmarkParams(*ini);
    const LandmarkParams defaults;
    std::vector<double> a, b;
    map::forEachLandmarkParam(loaded, [&](const char*, const char*, const auto& v) { a.push_back(v); });
    map::forEachLandmarkParam(defaults, [&](const char*, const char*, const auto& v) { b.push_back(v); });
    EXPECT_EQ(a, b);
    map::forEachLandmarkParam(defaults, [&](const char* section, const char* key, const auto&) {
        EXPECT_FALSE(ini->read_string(section, key, "", false).empty())
            << "[" << section << "] " << key << " is not documented in config/default.ini";
    });
}

TEST(LandmarkConfig, OverridesAreRead) {
    mrpt::config::CConfigFileMemory cfg(
        "[landmarks]\nmatch_height_m = 0.04\nconfirm_observations = 5\nuse_footprint = false\n"
        "[floors]\nfloor_merge_tolerance_m = 0.8\n");
    const LandmarkParams p = io::loadLandmarkParams(cfg);
    EXPECT_DOUBLE_EQ(p.match_height_m, 0.04);
    EXPECT_EQ(p.confirm_observations, 5);
    EXPECT_FALSE(p.use_footprint);
    EXPECT_DOUBLE_EQ(p.floor_merge_tolerance_m, 0.8);
    EXPECT_DOUBLE_EQ(p.match_distance_m, LandmarkParams{}.match_distance_m);  // untouched
}

struct BadValue {
    const char* ini;
    const char* expected;
};

class LandmarkConfigBad : public ::testing::TestWithParam<BadValue> {};

TEST_P(LandmarkConfigBad, ThrowsNamingTheKey) {
    mrpt::config::CConfigFileMemory cfg(GetParam().ini);
    try {
        io::loadLandmarkParams(cfg);
        FAIL() << "expected std::invalid_argument for " << GetParam().ini;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(GetParam().expected), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Values, LandmarkConfigBad,
    ::testing::Values(BadValue{"[landmarks]\nmatch_height_m = abc\n", "[landmarks] match_height_m"},
                      BadValue{"[landmarks]\nconfirm_observations = 0\n",
                               "[landmarks] confirm_observations"},
                      BadValue{"[landmarks]\nconfirm_observations = 2.5\n",
                               "[landmarks] confirm_observations: must be an integer"},
                      BadValue{"[landmarks]\nuse_footprint = maybe\n", "[landmarks] use_footprint"},
                      BadValue{"[floors]\nfloor_merge_tolerance_m = -1\n",
                               "[floors] floor_merge_tolerance_m"},
                      BadValue{"[landmarks]\nmatch_angle_deg = 1e999\n",
                               "[landmarks] match_angle_deg"}));

}  // namespace
}  // namespace stairmap
