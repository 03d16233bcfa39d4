// `stairmap detect` prints one JSON object that conforms to docs/detect.schema.json.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "CliRunner.h"
#include "support/JsonSchemaValidator.h"

namespace stairmap::test {
namespace {

using nlohmann::json;

json detectOutput(const std::string& name, const std::string& extra) {
    const std::string dir = cliScratchDir("DetectOutputSchema", name);
    const CliResult r = runStairmap(
        "detect '" + std::string(STAIRMAP_SOURCE_DIR) + "/datasets/clouds/ascending_0.pcd.gz'" + extra, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return json::parse(r.out);
}

TEST(DetectOutputSchema, OutputWithAndWithoutOptionsConforms) {
    const JsonSchemaValidator schema = JsonSchemaValidator::fromDocs("detect.schema.json");
    const json with_height = detectOutput("height", " --robot-height 0.35");
    ASSERT_FALSE(with_height.at("staircases").empty());  // a staircase exercises the nested schema
    EXPECT_TRUE(schema.validate(with_height).empty()) << ::testing::PrintToString(schema.validate(with_height));
    const json estimated = detectOutput("estimated", " --config '" + std::string(STAIRMAP_SOURCE_DIR) +
                                                         "/config/default.ini'");
    EXPECT_TRUE(estimated["input"]["robot_height_m"].is_null() || estimated["input"]["robot_height_m"].is_number());
    EXPECT_TRUE(schema.validate(estimated).empty()) << ::testing::PrintToString(schema.validate(estimated));
}

TEST(DetectOutputSchema, SchemaRejectsBrokenOutput) {
    const JsonSchemaValidator schema = JsonSchemaValidator::fromDocs("detect.schema.json");
    json doc = detectOutput("broken", " --robot-height 0.35");
    doc.erase("floor_z");
    doc["input"]["config"] = 3;
    doc["staircases"][0]["direction"] = "sideways";
    doc["staircases"][0]["steps"][0]["start"] = {1.0};
    const auto errors = schema.validate(doc);
    EXPECT_TRUE(anyErrorSays(errors, "$.floor_z: missing"));
    EXPECT_TRUE(anyErrorSays(errors, "$.input.config: expected"));
    EXPECT_TRUE(anyErrorSays(errors, "$.staircases[0].direction: not in enum"));
    EXPECT_TRUE(anyErrorSays(errors, "$.staircases[0].steps[0].start: too few items"));
}

}  // namespace
}  // namespace stairmap::test
