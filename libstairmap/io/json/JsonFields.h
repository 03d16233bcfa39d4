#pragma once
// Validating accessors for reading JSON documents: each throws std::runtime_error
// "<path>: <problem>" so that errors name the offending field.

#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace stairmap::io::json_fields {

const nlohmann::json& member(const nlohmann::json& object, const char* key,
                             const std::string& path);
const nlohmann::json& arrayMember(const nlohmann::json& object, const char* key,
                                  const std::string& path);
double finiteNumber(const nlohmann::json& value, const std::string& path);
int integer(const nlohmann::json& value, const std::string& path);
bool boolean(const nlohmann::json& value, const std::string& path);
std::string text(const nlohmann::json& value, const std::string& path);
Eigen::Vector3d vector3(const nlohmann::json& value, const std::string& path);
Eigen::Matrix2d matrix2(const nlohmann::json& value, const std::string& path);

nlohmann::json toJson(const Eigen::Vector3d& v);
nlohmann::json toJson(const Eigen::Matrix2d& m);

}  // namespace stairmap::io::json_fields
