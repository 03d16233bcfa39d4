// The written landmarks.json conforms to docs/landmarks.schema.json, checked by the tests' own
// validator for the draft-07 subset the schemas use (tests/support/JsonSchemaValidator.h).
#include <gtest/gtest.h>

#include <fstream>

#include "io/json/LandmarkJson.h"
#include "map/LandmarkTestMaps.h"
#include "support/JsonSchemaValidator.h"

namespace stairmap {
namespace {

using nlohmann::json;
using test::JsonSchemaValidator;

JsonSchemaValidator loadSchema() { return JsonSchemaValidator::fromDocs("landmarks.schema.json"); }

json writtenDocument() {
    const std::string path = test::scratchDir("schema") + "/landmarks.json";
    io::saveLandmarkMapAtomic(path, test::buildTestMap());
    std::ifstream in(path);
    return json::parse(in);
}

TEST(LandmarkSchema, WrittenDocumentConforms) {
    const json doc = writtenDocument();
    ASSERT_FALSE(doc.at("staircases").empty());
    const std::vector<std::string> errors = loadSchema().validate(doc);
    EXPECT_TRUE(errors.empty()) << ::testing::PrintToString(errors);
}

TEST(LandmarkSchema, ValidatorCatchesViolations) {
    // The check above is only meaningful if the schema rejects broken documents.
    const JsonSchemaValidator validator = loadSchema();
    json doc = writtenDocument();
    doc["staircases"][0].erase("top_floor");
    doc["staircases"][1]["location"] = {1.0, 2.0};
    doc["floors"][0]["z"] = "high";
    doc["version"] = 3;
    const std::vector<std::string> errors = validator.validate(doc);
    auto has = [&](const std::string& text) {
        return std::any_of(errors.begin(), errors.end(),
                           [&](const std::string& e) { return e.find(text) != std::string::npos; });
    };
    EXPECT_TRUE(has("$.staircases[0].top_floor: missing"));
    EXPECT_TRUE(has("$.staircases[1].location: too few items"));
    EXPECT_TRUE(has("$.floors[0].z: expected number"));
    EXPECT_TRUE(has("$.version: const mismatch"));
}

TEST(LandmarkSchema, StatesThePlausibilityBounds) {
    // The schema carries the bounds the loader checks (docs/landmarks.md): a far coordinate, a
    // 40 m rise and a negative variance are violations, the same values just inside are not.
    const JsonSchemaValidator validator = loadSchema();
    json doc = writtenDocument();
    doc["staircases"][0]["location"][0] = 1e12;
    doc["staircases"][0]["steps"][0]["end"][2] = -2e4;
    doc["staircases"][0]["step_height"] = 40.0;
    doc["staircases"][0]["steps"][0]["cov_rho_theta"][1][1] = -1e-6;
    const std::vector<std::string> errors = validator.validate(doc);
    EXPECT_TRUE(test::anyErrorSays(errors, "$.staircases[0].location[0]: above maximum"));
    EXPECT_TRUE(test::anyErrorSays(errors, "$.staircases[0].steps[0].end[2]: below minimum"));
    EXPECT_TRUE(test::anyErrorSays(errors, "$.staircases[0].step_height: above maximum"));
    EXPECT_TRUE(test::anyErrorSays(errors, "$.staircases[0].steps[0].cov_rho_theta[1][1]: below minimum"));
    EXPECT_EQ(errors.size(), 4u) << ::testing::PrintToString(errors);
    json inside = writtenDocument();
    inside["staircases"][0]["location"] = {-1e5, 1e5, 1e4};
    EXPECT_TRUE(validator.validate(inside).empty());
}

}  // namespace
}  // namespace stairmap
