// A loaded landmark map is checked for physical plausibility (docs/landmarks.md): every implausible
// value is refused with the source name and the JSON field path; values at the bounds load.
#include <gtest/gtest.h>

#include <functional>
#include <sstream>

#include "io/json/LandmarkJson.h"
#include "io/json/LandmarkPlausibility.h"
#include "map/LandmarkTestMaps.h"

namespace stairmap {
namespace {

using nlohmann::json;

json goodDocument() {
    std::ostringstream out;
    io::writeLandmarkState(out, test::buildTestMap().state(), test::buildTestMap().params());
    return json::parse(out.str());
}

LandmarkMapState load(const json& doc) {
    std::istringstream in(doc.dump());
    return io::readLandmarkState(in, "bad.json");
}

struct Implausible {
    const char* name;
    std::function<void(json&)> spoil;
    const char* message;  ///< expected after "bad.json: "
};

class RefusesImplausible : public ::testing::TestWithParam<Implausible> {};

TEST_P(RefusesImplausible, NamingSourceAndField) {
    json doc = goodDocument();
    ASSERT_GE(doc["staircases"].size(), 2u);
    GetParam().spoil(doc);
    try {
        load(doc);
        FAIL() << "accepted " << GetParam().name;
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(std::string("bad.json: ") + GetParam().message, 0), 0u) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(
    Fields, RefusesImplausible,
    ::testing::Values(
        Implausible{"FarX", [](json& d) { d["staircases"][0]["location"][0] = 1e12; },
                    "staircases[0].location[0]: 1e+12 is outside the world bound |x|, |y| <= 100000 m"},
        Implausible{"FarY", [](json& d) { d["staircases"][1]["steps"][0]["start"][1] = -100001.0; },
                    "staircases[1].steps[0].start[1]: -100001 is outside the world bound"},
        Implausible{"DeepZ", [](json& d) { d["staircases"][0]["steps"][1]["end"][2] = 10001.0; },
                    "staircases[0].steps[1].end[2]: 10001 is outside the world bound |z| <= 10000 m"},
        Implausible{"Rise", [](json& d) { d["staircases"][0]["step_height"] = 2.5; },
                    "staircases[0].step_height: 2.5 is outside [0, 2]"},
        Implausible{"NegativeRun", [](json& d) { d["staircases"][0]["step_depth"] = -0.1; },
                    "staircases[0].step_depth: -0.1 is outside [0, 3]"},
        Implausible{"Width", [](json& d) { d["staircases"][1]["step_width"] = 1e3; },
                    "staircases[1].step_width: 1000 is outside [0, 100]"},
        Implausible{"Slope", [](json& d) { d["staircases"][0]["slope_rad"] = 2.0; },
                    "staircases[0].slope_rad: 2 is outside"},
        Implausible{"Heading", [](json& d) { d["staircases"][0]["heading_rad"] = 1e6; },
                    "staircases[0].heading_rad: 1e+06 is outside"},
        Implausible{"Variance", [](json& d) { d["staircases"][0]["steps"][0]["cov_rho_theta"][0][0] = -1e-3; },
                    "staircases[0].steps[0].cov_rho_theta[0][0]: -0.001 is outside [0, 10000]"},
        Implausible{"Covariance", [](json& d) { d["staircases"][0]["steps"][0]["cov_rho_theta"][0][1] = 1e9; },
                    "staircases[0].steps[0].cov_rho_theta[0][1]: 1e+09 is outside"},
        Implausible{"Stamps", [](json& d) { d["staircases"][0]["last_seen_s"] = -5.0; },
                    "staircases[0].last_seen_s: -5 is outside"},
        Implausible{"FloorLevel", [](json& d) { d["continuation"]["floor_levels"][0]["z"] = 2e4; },
                    "continuation.floor_levels[0].z: 20000 is outside"},
        Implausible{"FloorSum", [](json& d) { d["continuation"]["floor_levels"][0]["robot_z_sum"] = 1e300; },
                    "continuation.floor_levels[0].robot_z_sum: 1e+300 is outside"},
        Implausible{"ReportedFloor", [](json& d) { d["floors"][0]["z"] = -1e12; },
                    "floors[0].z: -1e+12 is outside the world bound"},
        Implausible{"Transit",
                    [](json& d) {
                        d["continuation"]["transits"] = json::array(
                            {{{"stamp_s", 1.0}, {"floor_path", {{0, 0, 0}, {1, 0, 0}, {1e7, 0, 0}}}}});
                    },
                    "continuation.transits[0].floor_path[2][0]: 1e+07 is outside"},
        Implausible{"Params", [](json& d) { d["params"]["landmarks"]["match_distance_m"] = -1.0; },
                    "params: "}),
    [](const ::testing::TestParamInfo<Implausible>& param_info) { return std::string(param_info.param.name); });

TEST(LandmarkPlausibility, ValuesAtTheBoundsLoad) {
    json doc = goodDocument();
    doc["staircases"][0]["location"] = {-1e5, 1e5, -1e4};
    doc["staircases"][0]["steps"][0]["start"] = {1e5, -1e5, 1e4};
    doc["staircases"][0]["step_height"] = 2.0;
    doc["staircases"][0]["step_width"] = 0.0;
    const LandmarkMapState state = load(doc);
    EXPECT_EQ(state.staircases[0].stairs.location.x(), -1e5);
    EXPECT_EQ(state.staircases[0].stairs.steps[0].start.z(), 1e4);
}

}  // namespace
}  // namespace stairmap
