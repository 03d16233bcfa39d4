#include "io/config/LandmarkConfig.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "map/LandmarkParamsFields.h"

namespace stairmap::io {
namespace {

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\n\"");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r\n\"") - b + 1);
}

[[noreturn]] void fail(const std::string& section, const std::string& key, const std::string& what) {
    throw std::invalid_argument("[" + section + "] " + key + ": " + what);
}

double parseNumber(const std::string& text, const std::string& section, const std::string& key) {
    std::istringstream in(text);
    double v = 0.0;
    in >> v;
    if (in.fail() || !std::isfinite(v) || !(in >> std::ws).eof())
        fail(section, key, "'" + text + "' is not a finite number");
    return v;
}

bool parseBool(std::string text, const std::string& section, const std::string& key) {
    std::transform(text.begin(), text.end(), text.begin(), ::tolower);
    if (text == "true" || text == "1" || text == "yes") return true;
    if (text == "false" || text == "0" || text == "no") return false;
    fail(section, key, "'" + text + "' is not a boolean (true/false)");
}

template <class T>
void parseInto(const std::string& text, const std::string& section, const std::string& key, T& out) {
    if constexpr (std::is_same_v<T, bool>) {
        out = parseBool(text, section, key);
    } else if constexpr (std::is_same_v<T, int>) {
        const double v = parseNumber(text, section, key);
        if (v != std::floor(v) || std::abs(v) > 1e9) fail(section, key, "must be an integer");
        out = static_cast<int>(v);
    } else {
        out = parseNumber(text, section, key);
    }
}

/// "LandmarkParams.<field>: ..." from validateLandmarkParams -> "[section] <field>: ...".
[[noreturn]] void rethrowWithSection(const std::invalid_argument& e, const LandmarkParams& p,
                                     const std::string& landmarks_section,
                                     const std::string& floors_section) {
    const std::string what = e.what();
    std::string result = what;
    map::forEachLandmarkParam(p, [&](const char* section, const char* key, const auto&) {
        const std::string prefix = std::string("LandmarkParams.") + key + ":";
        if (what.rfind(prefix, 0) == 0) {
            const std::string& sec =
                std::string(section) == "floors" ? floors_section : landmarks_section;
            result = "[" + sec + "] " + key + what.substr(prefix.size() - 1);
        }
    });
    throw std::invalid_argument(result);
}

}  // namespace

LandmarkParams loadLandmarkParams(const mrpt::config::CConfigFileBase& cfg,
                                  const std::string& landmarks_section,
                                  const std::string& floors_section) {
    LandmarkParams p;
    map::forEachLandmarkParam(p, [&](const char* section, const char* key, auto& field) {
        const std::string& sec =
            std::string(section) == "floors" ? floors_section : landmarks_section;
        const std::string text = trimmed(cfg.read_string(sec, key, "", false));
        if (!text.empty()) parseInto(text, sec, key, field);
    });
    try {
        validateLandmarkParams(p);
    } catch (const std::invalid_argument& e) {
        rethrowWithSection(e, p, landmarks_section, floors_section);
    }
    return p;
}

}  // namespace stairmap::io
