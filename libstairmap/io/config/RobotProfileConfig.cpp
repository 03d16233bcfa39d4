#include "io/config/RobotProfileConfig.h"

#include <filesystem>
#include <stdexcept>

#include "io/config/IniFieldReader.h"
#include "io/config/IniFile.h"
#include "io/config/IniKeys.h"
#include "io/config/IniSyntax.h"

namespace stairmap::io {
namespace {

constexpr const char* kSection = "robot";

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
    const std::vector<IniLine> lines = lexIniFile(path);  // malformed lines fail first
    if (!cfg->sectionExists(kSection)) throw std::runtime_error(path + ": no [robot] section");
    const KeyRecorder recorder(*cfg);  // learns the valid keys from readFields itself
    const IniFieldReader reader(recorder, path);
    exporting::RobotProfile p = readFields(reader, std::filesystem::path(path).stem().string());
    checkIniKeys(lines, recorder.keys(), path);
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
