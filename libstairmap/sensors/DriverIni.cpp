#include "sensors/DriverIni.h"

#include "io/rawlog/MrptErrorText.h"

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <stdexcept>

namespace stairmap::sensors {
namespace {

namespace fs = std::filesystem;

bool hasPoseKeys(const mrpt::config::CConfigFile& cfg, const std::string& section) {
    for (const char* key : {"pose_x", "pose_y", "pose_z", "pose_yaw", "pose_pitch", "pose_roll"}) {
        if (cfg.keyExists(section, key)) return true;
    }
    return false;
}

std::string resolvePcap(const std::string& ini_path, const std::string& given) {
    if (given.empty() || fs::path(given).is_absolute()) return given;
    std::error_code ec;
    if (fs::exists(given, ec)) return given;
    return (fs::path(ini_path).parent_path() / given).string();
}

DriverSection readSection(const mrpt::config::CConfigFile& cfg, const std::string& ini_path,
                          const std::string& name) {
    DriverSection s;
    s.ini_path = ini_path;
    s.section = name;
    s.driver = cfg.read_string(name, "driver", "");
    if (s.driver.empty()) throw std::runtime_error(s.identity() + ": no 'driver' key (e.g. driver = CVelodyneScanner)");
    s.process_rate_hz = cfg.read_double(name, "process_rate", 0.0);
    if (s.driver != "CVelodyneScanner" && !(s.process_rate_hz > 0.0)) {
        throw std::runtime_error(s.identity() + ": process_rate must be set to a rate > 0 [Hz]");
    }
    s.has_pose_keys = hasPoseKeys(cfg, name);
    s.pcap_input = resolvePcap(ini_path, cfg.read_string(name, "pcap_input", ""));
    s.pcap_read_once = cfg.read_bool(name, "pcap_read_once", false);
    s.pcap_read_fast = cfg.read_bool(name, "pcap_read_fast", false);
    return s;
}

}  // namespace

std::vector<DriverSection> readDriverSections(const std::string& ini_path) {
    std::error_code ec;
    if (!fs::is_regular_file(ini_path, ec)) {  // CConfigFile would silently read nothing
        throw std::runtime_error(ini_path + (fs::exists(ini_path, ec) ? ": not a file" : ": no such file"));
    }
    std::vector<DriverSection> out;
    try {
        const mrpt::config::CConfigFile cfg(ini_path);
        std::vector<std::string> sections;
        cfg.getAllSections(sections);
        for (const auto& name : sections) {
            if (name.empty() || name == "global") continue;  // rawlog-grabber's application section
            out.push_back(readSection(cfg, ini_path, name));
        }
    } catch (const std::runtime_error&) {
        throw;
    } catch (const std::exception& e) {  // MRPT's parser: a malformed value or line
        throw std::runtime_error(ini_path + ": " + io::mrptErrorText(e));
    }
    if (out.empty()) throw std::runtime_error(ini_path + ": no sensor section (e.g. [LIDAR] with driver = CVelodyneScanner)");
    return out;
}

}  // namespace stairmap::sensors
