#include "io/config/IniFieldReader.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace stairmap::io {

namespace {
std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n\"");
    if (b == std::string::npos) return "";
    const auto e = s.find_last_not_of(" \t\r\n\"");
    return s.substr(b, e - b + 1);
}

bool parseDouble(const std::string& text, double& out) {
    std::istringstream in(text);
    in >> out;
    if (in.fail() || !std::isfinite(out)) return false;
    in >> std::ws;
    return in.eof();
}
}  // namespace

bool IniFieldReader::has(const std::string& section, const std::string& key) const {
    return !trim(cfg_.read_string(section, key, "", false)).empty();
}

std::string IniFieldReader::getString(const std::string& section, const std::string& key,
                                      const std::string& fallback) const {
    const std::string v = trim(cfg_.read_string(section, key, "", false));
    return v.empty() ? fallback : v;
}

double IniFieldReader::getDouble(const std::string& section, const std::string& key,
                                 double fallback) const {
    const std::string v = getString(section, key, "");
    if (v.empty()) return fallback;
    double out = 0.0;
    if (!parseDouble(v, out)) fail(section, key, "'" + v + "' is not a finite number");
    return out;
}

int IniFieldReader::getInt(const std::string& section, const std::string& key, int fallback) const {
    const double v = getDouble(section, key, fallback);
    if (v != std::floor(v) || std::abs(v) > 1e9) fail(section, key, "must be an integer");
    return static_cast<int>(v);
}

bool IniFieldReader::getBool(const std::string& section, const std::string& key, bool fallback) const {
    std::string v = getString(section, key, "");
    if (v.empty()) return fallback;
    std::transform(v.begin(), v.end(), v.begin(), ::tolower);
    if (v == "true" || v == "1" || v == "yes") return true;
    if (v == "false" || v == "0" || v == "no") return false;
    fail(section, key, "'" + v + "' is not a boolean (true/false)");
}

std::vector<std::vector<double>> IniFieldReader::getGroups(const std::string& section,
                                                           const std::string& key,
                                                           std::size_t per_group) const {
    std::string text = getString(section, key, "");
    std::replace(text.begin(), text.end(), ',', ';');
    std::vector<std::vector<double>> groups;
    std::istringstream all(text);
    std::string group_text;
    while (std::getline(all, group_text, ';')) {
        if (trim(group_text).empty()) continue;
        std::istringstream in(group_text);
        std::vector<double> values;
        std::string token;
        while (in >> token) {
            double v = 0.0;
            if (!parseDouble(token, v)) fail(section, key, "'" + token + "' is not a finite number");
            values.push_back(v);
        }
        if (per_group > 0 && values.size() != per_group) {
            fail(section, key, "group '" + trim(group_text) + "' must hold " +
                                   std::to_string(per_group) + " numbers");
        }
        groups.push_back(values);
    }
    return groups;
}

std::vector<double> IniFieldReader::getNumbers(const std::string& section, const std::string& key) const {
    std::vector<double> all;
    for (const auto& g : getGroups(section, key, 0)) all.insert(all.end(), g.begin(), g.end());
    return all;
}

void IniFieldReader::fail(const std::string& section, const std::string& key,
                          const std::string& what) const {
    throw std::runtime_error(path_ + ": [" + section + "] " + key + ": " + what);
}

}  // namespace stairmap::io
