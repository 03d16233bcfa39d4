#include "io/config/ConfigFile.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <stdexcept>

#include "io/config/IniFile.h"
#include "io/config/IniSyntax.h"
#include "io/config/MapperConfig.h"

namespace stairmap::io {

const IniKeys& configFileKeys() {
    static const IniKeys keys = [] {
        const mrpt::config::CConfigFileMemory empty;
        const KeyRecorder recorder(empty);
        loadMapperParams(recorder);  // defaults only: every key is asked for, none is found
        return recorder.keys();
    }();
    return keys;
}

std::unique_ptr<mrpt::config::CConfigFile> openConfigFile(const std::string& path) {
    auto cfg = openIniFile(path);
    checkIniKeys(lexIniFile(path), configFileKeys(), path);
    return cfg;
}

DetectorConfig loadDetectorConfigFile(const std::string& path) {
    const auto cfg = openConfigFile(path);
    try {
        return loadDetectorConfig(*cfg, "detector");
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace stairmap::io
