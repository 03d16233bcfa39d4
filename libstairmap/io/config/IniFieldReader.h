#pragma once
// Strict typed reads from an MRPT INI file: a value that is present but malformed or out of range
// throws std::runtime_error "<file>: [section] key: <problem>" (MRPT's own readers would silently
// return 0 for text). Missing keys give the caller's default.

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace stairmap::io {

class IniFieldReader {
public:
    IniFieldReader(const mrpt::config::CConfigFileBase& cfg, std::string path)
        : cfg_(cfg), path_(std::move(path)) {}

    bool has(const std::string& section, const std::string& key) const;
    std::string getString(const std::string& section, const std::string& key,
                          const std::string& fallback) const;
    double getDouble(const std::string& section, const std::string& key, double fallback) const;
    int getInt(const std::string& section, const std::string& key, int fallback) const;
    bool getBool(const std::string& section, const std::string& key, bool fallback) const;
    /// Numbers separated by blanks; each group separated by ';' or ','. Every group must hold
    /// exactly `per_group` numbers, e.g. "1 2 0; 3 4 0" with per_group 3.
    std::vector<std::vector<double>> getGroups(const std::string& section, const std::string& key,
                                               std::size_t per_group) const;
    /// Same as getGroups with a single group of any size (e.g. a list of elevations).
    std::vector<double> getNumbers(const std::string& section, const std::string& key) const;

    /// Throws "<file>: [section] key: what".
    [[noreturn]] void fail(const std::string& section, const std::string& key,
                           const std::string& what) const;
    const std::string& path() const { return path_; }

private:
    const mrpt::config::CConfigFileBase& cfg_;
    std::string path_;
};

}  // namespace stairmap::io
