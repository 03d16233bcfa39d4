// The written landmarks.json conforms to docs/landmarks.schema.json. A small validator for the
// draft-07 subset the schema uses (type, required, properties, items, minItems, maxItems, minimum,
// enum, const, local $ref) keeps the test free of external packages.
#include <gtest/gtest.h>

#include <fstream>

#include "io/json/LandmarkJson.h"
#include "map/LandmarkTestMaps.h"

namespace stairmap {
namespace {

using nlohmann::json;

class MiniSchemaValidator {
public:
    explicit MiniSchemaValidator(json root) : root_(std::move(root)) {}

    /// Returns the violations found ("<path>: <what>"), empty if the document conforms.
    std::vector<std::string> validate(const json& doc) const {
        std::vector<std::string> errors;
        check(doc, root_, "$", errors);
        return errors;
    }

private:
    const json& resolve(const json& schema) const {
        if (!schema.contains("$ref")) return schema;
        const std::string ref = schema["$ref"];  // "#/definitions/<name>"
        return root_.at("definitions").at(ref.substr(ref.rfind('/') + 1));
    }

    static bool hasType(const json& v, const std::string& type) {
        if (type == "object") return v.is_object();
        if (type == "array") return v.is_array();
        if (type == "string") return v.is_string();
        if (type == "boolean") return v.is_boolean();
        if (type == "integer") return v.is_number_integer();
        if (type == "number") return v.is_number();
        return false;
    }

    void check(const json& v, const json& raw, const std::string& path,
               std::vector<std::string>& errors) const {
        const json& s = resolve(raw);
        if (s.contains("type") && !hasType(v, s["type"])) {
            errors.push_back(path + ": expected " + s["type"].get<std::string>());
            return;
        }
        if (s.contains("const") && v != s["const"]) errors.push_back(path + ": const mismatch");
        if (s.contains("enum") && std::find(s["enum"].begin(), s["enum"].end(), v) == s["enum"].end())
            errors.push_back(path + ": not in enum");
        if (s.contains("minimum") && v.is_number() && v.get<double>() < s["minimum"].get<double>())
            errors.push_back(path + ": below minimum");
        if (v.is_object()) checkObject(v, s, path, errors);
        if (v.is_array()) checkArray(v, s, path, errors);
    }

    void checkObject(const json& v, const json& s, const std::string& path,
                     std::vector<std::string>& errors) const {
        const json required = s.value("required", json::array());
        const json properties = s.value("properties", json::object());
        for (const json& key : required) {
            if (!v.contains(key.get<std::string>()))
                errors.push_back(path + "." + key.get<std::string>() + ": missing");
        }
        for (const auto& [key, sub] : properties.items()) {
            if (v.contains(key)) check(v[key], sub, path + "." + key, errors);
        }
    }

    void checkArray(const json& v, const json& s, const std::string& path,
                    std::vector<std::string>& errors) const {
        if (s.contains("minItems") && v.size() < s["minItems"].get<std::size_t>())
            errors.push_back(path + ": too few items");
        if (s.contains("maxItems") && v.size() > s["maxItems"].get<std::size_t>())
            errors.push_back(path + ": too many items");
        if (!s.contains("items")) return;
        for (std::size_t i = 0; i < v.size(); ++i) {
            check(v[i], s["items"], path + "[" + std::to_string(i) + "]", errors);
        }
    }

    json root_;
};

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
