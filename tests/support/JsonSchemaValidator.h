#pragma once
// A small JSON Schema (draft-07) validator for the subset stairmap's schemas in docs/ use: type
// (a name or a list of names), required, properties, additionalProperties as a schema (maps keyed
// by name; booleans are not checked), items (one schema, or a list for tuples),
// minItems, maxItems, minimum, maximum, exclusiveMinimum, enum, const and local
// "#/definitions/<name>" references. Written for the tests, independently of the writers, so that
// what stairmap writes is checked against the documented contract rather than against itself.

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace stairmap::test {

class JsonSchemaValidator {
public:
    explicit JsonSchemaValidator(nlohmann::json root) : root_(std::move(root)) {}

    /// Loads docs/<name> from the source tree.
    static JsonSchemaValidator fromDocs(const std::string& name) {
        std::ifstream in(std::string(STAIRMAP_SOURCE_DIR) + "/docs/" + name);
        if (!in) throw std::runtime_error("cannot open docs/" + name);
        return JsonSchemaValidator(nlohmann::json::parse(in));
    }

    /// The violations found ("<path>: <what>"), empty if the document conforms.
    std::vector<std::string> validate(const nlohmann::json& doc) const {
        std::vector<std::string> errors;
        check(doc, root_, "$", errors);
        return errors;
    }

private:
    using json = nlohmann::json;

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
        if (type == "null") return v.is_null();
        return false;
    }

    static bool hasAnyType(const json& v, const json& types) {
        if (types.is_string()) return hasType(v, types);
        return std::any_of(types.begin(), types.end(), [&](const json& t) { return hasType(v, t); });
    }

    void check(const json& v, const json& raw, const std::string& path,
               std::vector<std::string>& errors) const {
        const json& s = resolve(raw);
        if (s.contains("type") && !hasAnyType(v, s["type"])) {
            const json& t = s["type"];
            errors.push_back(path + ": expected " + (t.is_string() ? t.get<std::string>() : t.dump()));
            return;
        }
        if (s.contains("const") && v != s["const"]) errors.push_back(path + ": const mismatch");
        if (s.contains("enum") && std::find(s["enum"].begin(), s["enum"].end(), v) == s["enum"].end())
            errors.push_back(path + ": not in enum");
        if (v.is_number()) checkNumber(v.get<double>(), s, path, errors);
        if (v.is_object()) checkObject(v, s, path, errors);
        if (v.is_array()) checkArray(v, s, path, errors);
    }

    static void checkNumber(double x, const json& s, const std::string& path,
                            std::vector<std::string>& errors) {
        if (s.contains("minimum") && x < s["minimum"].get<double>()) errors.push_back(path + ": below minimum");
        if (s.contains("maximum") && x > s["maximum"].get<double>()) errors.push_back(path + ": above maximum");
        if (s.contains("exclusiveMinimum") && x <= s["exclusiveMinimum"].get<double>())
            errors.push_back(path + ": not above exclusiveMinimum");
    }

    void checkObject(const json& v, const json& s, const std::string& path,
                     std::vector<std::string>& errors) const {
        const json required = s.value("required", json::array());
        const json properties = s.value("properties", json::object());  // a named copy: items() refers to it
        for (const json& key : required) {
            if (!v.contains(key.get<std::string>())) errors.push_back(path + "." + key.get<std::string>() + ": missing");
        }
        for (const auto& [key, sub] : properties.items()) {
            if (v.contains(key)) check(v[key], sub, path + "." + key, errors);
        }
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
        const json& items = s["items"];
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (items.is_array() && i >= items.size()) break;  // tuple form: extra items are free
            check(v[i], items.is_array() ? items[i] : items, path + "[" + std::to_string(i) + "]", errors);
        }
    }

    json root_;
};

/// True when one of `errors` contains `text`.
inline bool anyErrorSays(const std::vector<std::string>& errors, const std::string& text) {
    return std::any_of(errors.begin(), errors.end(),
                       [&](const std::string& e) { return e.find(text) != std::string::npos; });
}

}  // namespace stairmap::test
