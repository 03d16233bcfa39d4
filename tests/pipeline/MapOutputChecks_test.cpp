// Everything `stairmap map` writes conforms to its schema in docs/ (landmarks.json, each line of
// detections.jsonl, stats.json), and a loaded map (--map-in) is checked for physical plausibility:
// a schema-valid landmarks.json with an absurd value is refused naming the file and the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "pipeline/CliRunner.h"
#include "support/JsonSchemaValidator.h"

namespace stairmap::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::JsonSchemaValidator;

std::string mapArgs(const fs::path& out, const std::string& extra = "") {
    return "map '" + datasetPath("two_floor/two_floor.rawlog") + "' --poses '" +
           datasetPath("two_floor/poses.tum") + "' --config '" + STAIRMAP_SOURCE_DIR +
           "/config/sim_legged_vlp16.ini' --out '" + out.string() + "'" + extra;
}

class MapOutputs : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = scratch("MapOutputChecks").string();
        const CliResult r = runStairmap(mapArgs(fs::path(dir_) / "out"), dir_);
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    static fs::path out() { return fs::path(dir_) / "out"; }
    static std::string dir_;
};
std::string MapOutputs::dir_;

void expectConforms(const json& doc, const std::string& schema, const std::string& what) {
    const auto errors = JsonSchemaValidator::fromDocs(schema).validate(doc);
    EXPECT_TRUE(errors.empty()) << what << " vs docs/" << schema << ": " << ::testing::PrintToString(errors);
}

TEST_F(MapOutputs, LandmarksJsonConformsToItsSchema) {
    const json doc = readJson(out() / "landmarks.json");
    ASSERT_FALSE(doc.at("staircases").empty());
    expectConforms(doc, "landmarks.schema.json", "landmarks.json");
}

TEST_F(MapOutputs, EveryDetectionRecordConformsToItsSchema) {
    std::ifstream in(out() / "detections.jsonl");
    std::string line;
    int lines = 0;
    while (std::getline(in, line)) {
        expectConforms(json::parse(line), "detections.schema.json", "detections.jsonl line " + std::to_string(++lines));
    }
    EXPECT_GT(lines, 0);
}

TEST_F(MapOutputs, StatsJsonConformsToItsSchema) {
    expectConforms(readJson(out() / "stats.json"), "stats.schema.json", "stats.json");
}

TEST_F(MapOutputs, SchemasRejectBrokenRecords) {
    // The checks above mean something only if the schemas catch what a broken writer would do.
    std::ifstream in(out() / "detections.jsonl");
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    json record = json::parse(line);
    record.erase("landmark_id");
    record["robot_pose"]["quaternion_xyzw"] = {0.0, 0.0, 1.0};
    record["staircase"]["step_height"] = -0.1;
    const auto errors = JsonSchemaValidator::fromDocs("detections.schema.json").validate(record);
    EXPECT_TRUE(test::anyErrorSays(errors, "$.landmark_id: missing"));
    EXPECT_TRUE(test::anyErrorSays(errors, "$.robot_pose.quaternion_xyzw: too few items"));
    EXPECT_TRUE(test::anyErrorSays(errors, "$.staircase.step_height: below minimum"));
    json stats = readJson(out() / "stats.json");
    stats["scans"] = -1;
    stats["source"].erase("scans_read");
    const auto stats_errors = JsonSchemaValidator::fromDocs("stats.schema.json").validate(stats);
    EXPECT_TRUE(test::anyErrorSays(stats_errors, "$.scans: below minimum"));
    EXPECT_TRUE(test::anyErrorSays(stats_errors, "$.source.scans_read: missing"));
}

TEST_F(MapOutputs, MapInRefusesImplausibleValuesNamingFileAndField) {
    struct Case {
        std::string name, field;
        std::function<void(json&)> spoil;
    };
    const std::vector<Case> cases = {
        {"far", "staircases[0].location[0]", [](json& d) { d["staircases"][0]["location"][0] = 1e12; }},
        {"deep", "staircases[1].steps[2].end[2]", [](json& d) { d["staircases"][1]["steps"][2]["end"][2] = -5e4; }},
        {"rise", "staircases[0].step_height", [](json& d) { d["staircases"][0]["step_height"] = 40.0; }},
        {"variance", "staircases[0].steps[0].cov_rho_theta[1][1]",
         [](json& d) { d["staircases"][0]["steps"][0]["cov_rho_theta"][1][1] = -1.0; }},
        {"floor", "continuation.floor_levels[0].z",
         [](json& d) { d["continuation"]["floor_levels"][0]["z"] = 3e5; }},
        {"params", "match_distance_m", [](json& d) { d["params"]["landmarks"]["match_distance_m"] = -1.0; }},
    };
    const json good = readJson(out() / "landmarks.json");
    for (const Case& c : cases) {
        const fs::path dir = scratch("MapInChecks_" + c.name);
        json doc = good;
        c.spoil(doc);
        const fs::path bad = dir / "bad.json";
        std::ofstream(bad) << doc.dump(2);
        const CliResult r = runStairmap(mapArgs(dir / "out", " --map-in '" + bad.string() + "'"), dir);
        EXPECT_EQ(r.exit_code, 2) << c.name << ": " << r.err;
        EXPECT_NE(r.err.find(bad.string()), std::string::npos) << c.name << ": " << r.err;
        EXPECT_NE(r.err.find(c.field), std::string::npos) << c.name << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.name << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "out" / "landmarks.json")) << c.name;
    }
}

}  // namespace
}  // namespace stairmap::testing
