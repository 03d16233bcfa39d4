#include "io/config/RobotProfileConfig.h"

#include <filesystem>
#include <set>
#include <stdexcept>

#include "io/config/IniFieldReader.h"
#include "io/config/IniFile.h"

namespace stairmap::io {
namespace {

constexpr const char* kSection = "robot";

const std::set<std::string>& knownKeys() {
    static const std::set<std::string> keys = {"name",
                                               "max_rise_m",
                                               "min_run_m",
                                               "min_width_m",
                                               "max_slope_deg",
                                               "max_steps_without_landing",
                                               "can_ascend",
                                               "can_descend",
                                               "footprint_length_m",
                                               "footprint_width_m",
                                               "clearance_m",
                                               "height_m"};
    return keys;
}

void checkSectionAndKeys(const mrpt::config::CConfigFile& cfg, const IniFieldReader& r) {
    std::vector<std::string> sections;
    cfg.getAllSections(sections);
    bool found = false;
    for (const auto& s : sections) found = found || s == kSection;
    if (!found) throw std::runtime_error(r.path() + ": no [robot] section");
    std::vector<std::string> keys;
    cfg.getAllKeys(kSection, keys);
    for (const auto& k : keys) {
        if (!knownKeys().count(k)) r.fail(kSection, k, "unknown key");
    }
}

exporting::RobotProfile readFields(const IniFieldReader& r, const std::string& stem) {
    exporting::RobotProfile p;
    p.name = r.getString(kSection, "name", stem);
    p.max_rise_m = r.getDouble(kSection, "max_rise_m", p.max_rise_m);
    p.min_run_m = r.getDouble(kSection, "min_run_m", p.min_run_m);
    p.min_width_m = r.getDouble(kSection, "min_width_m", p.min_width_m);
    p.max_slope_deg = r.getDouble(kSection, "max_slope_deg", p.max_slope_deg);
    p.max_steps_without_landing =
        r.getInt(kSection, "max_steps_without_landing", p.max_steps_without_landing);
    p.can_ascend = r.getBool(kSection, "can_ascend", p.can_ascend);
    p.can_descend = r.getBool(kSection, "can_descend", p.can_descend);
    p.footprint_length_m = r.getDouble(kSection, "footprint_length_m", p.footprint_length_m);
    p.footprint_width_m = r.getDouble(kSection, "footprint_width_m", p.footprint_width_m);
    p.clearance_m = r.getDouble(kSection, "clearance_m", p.clearance_m);
    p.height_m = r.getDouble(kSection, "height_m", p.height_m);
    return p;
}

}  // namespace

exporting::RobotProfile loadRobotProfile(const std::string& path) {
    const auto cfg = openIniFile(path);
    const IniFieldReader reader(*cfg, path);
    checkSectionAndKeys(*cfg, reader);
    exporting::RobotProfile p = readFields(reader, std::filesystem::path(path).stem().string());
    try {
        exporting::validateRobotProfile(p);
    } catch (const std::invalid_argument& e) {
        // "RobotProfile.<key>: <problem>" -> "<path>: [robot] <key>: <problem>"
        const std::string what = e.what();
        const std::string prefix = "RobotProfile.";
        throw std::runtime_error(path + ": [robot] " +
                                 (what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what));
    }
    return p;
}

}  // namespace stairmap::io
