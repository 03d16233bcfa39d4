#pragma once
// Internal to SceneIni: the readers of the [sensor], [robot], [trajectory]/robot and [clouds]
// sections, shared by SceneIni.cpp and SceneIniSensor.cpp.

#include "io/config/IniFieldReader.h"
#include "sim/SimulationConfig.h"

namespace stairmap::io::detail {

void loadSensorSection(const IniFieldReader& ini, sim::SimulationConfig& config);
void loadRobotRuns(const IniFieldReader& ini, sim::SimulationConfig& config);
void loadCloudSection(const IniFieldReader& ini, sim::SimulationConfig& config);

/// Runs `validate`, turning its std::invalid_argument ("field: what") into
/// "<file>: [section] field: what".
template <typename Fn>
void checked(const IniFieldReader& ini, const std::string& section, Fn&& validate) {
    try {
        validate();
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(ini.path() + ": [" + section + "] " + e.what());
    }
}

}  // namespace stairmap::io::detail
