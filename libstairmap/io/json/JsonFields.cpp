#include "io/json/JsonFields.h"

#include <cmath>
#include <stdexcept>

namespace stairmap::io::json_fields {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
    throw std::runtime_error(path + ": " + problem);
}

std::string child(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
}

}  // namespace

const nlohmann::json& member(const nlohmann::json& object, const char* key,
                             const std::string& path) {
    if (!object.is_object()) fail(path.empty() ? "document" : path, "expected an object");
    const auto it = object.find(key);
    if (it == object.end()) fail(child(path, key), "missing");
    return *it;
}

const nlohmann::json& arrayMember(const nlohmann::json& object, const char* key,
                                  const std::string& path) {
    const nlohmann::json& value = member(object, key, path);
    if (!value.is_array()) fail(child(path, key), "expected an array");
    return value;
}

double finiteNumber(const nlohmann::json& value, const std::string& path) {
    if (!value.is_number()) fail(path, "expected a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(path, "expected a finite number");
    return x;
}

int integer(const nlohmann::json& value, const std::string& path) {
    if (!value.is_number_integer()) fail(path, "expected an integer");
    const auto x = value.get<long long>();
    if (x < -2147483647LL || x > 2147483647LL) fail(path, "integer out of range");
    return static_cast<int>(x);
}

bool boolean(const nlohmann::json& value, const std::string& path) {
    if (!value.is_boolean()) fail(path, "expected true or false");
    return value.get<bool>();
}

std::string text(const nlohmann::json& value, const std::string& path) {
    if (!value.is_string()) fail(path, "expected a string");
    return value.get<std::string>();
}

Eigen::Vector3d vector3(const nlohmann::json& value, const std::string& path) {
    if (!value.is_array() || value.size() != 3) fail(path, "expected an array of 3 finite numbers");
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number() || !std::isfinite(value[i].get<double>()))
            fail(path, "expected an array of 3 finite numbers");
        v[i] = value[i].get<double>();
    }
    return v;
}

Eigen::Matrix2d matrix2(const nlohmann::json& value, const std::string& path) {
    if (!value.is_array() || value.size() != 2) fail(path, "expected a 2x2 array of numbers");
    Eigen::Matrix2d m;
    for (int r = 0; r < 2; ++r) {
        const nlohmann::json& row = value[r];
        if (!row.is_array() || row.size() != 2) fail(path, "expected a 2x2 array of numbers");
        for (int c = 0; c < 2; ++c) {
            m(r, c) = finiteNumber(row[c], path + "[" + std::to_string(r) + "]");
        }
    }
    return m;
}

nlohmann::json toJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json toJson(const Eigen::Matrix2d& m) {
    return {{m(0, 0), m(0, 1)}, {m(1, 0), m(1, 1)}};
}

}  // namespace stairmap::io::json_fields
