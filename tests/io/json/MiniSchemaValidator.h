#pragma once
// A small JSON-schema validator for the draft-07 subset our schemas use (type, required,
// properties, additionalProperties as a schema, items, minItems, maxItems, minimum, enum, const,
// local $ref), so schema tests need no external package.

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace stairmap::test {

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
        // additionalProperties as a schema (maps keyed by name); booleans are not checked.
        const json extra = s.value("additionalProperties", json(true));
        if (!extra.is_object()) return;
        for (const auto& [key, value] : v.items()) {
            if (!properties.contains(key)) check(value, extra, path + "." + key, errors);
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

}  // namespace stairmap::test
