// The written landmarks.json conforms to docs/landmarks.schema.json (json/MiniSchemaValidator.h).
#include <gtest/gtest.h>

#include <fstream>

#include "io/json/LandmarkJson.h"
#include "io/json/MiniSchemaValidator.h"
#include "map/LandmarkTestMaps.h"

namespace stairmap {
namespace {

using nlohmann::json;
using test::MiniSchemaValidator;

MiniSchemaValidator loadSchema() {
    std::ifstream in(std::string(STAIRMAP_SOURCE_DIR) + "/docs/landmarks.schema.json");
    EXPECT_TRUE(in.good());
    return MiniSchemaValidator(json::parse(in));
}

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
    const MiniSchemaValidator validator = loadSchema();
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

}  // namespace
}  // namespace stairmap
