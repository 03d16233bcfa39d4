#pragma once
// Loading the detector's parameters from an MRPT-style INI section (config/default.ini, [detector]).

#include <mrpt/config/CConfigFileBase.h>

#include <optional>
#include <string>

#include "core/DetectorParams.h"

namespace stairmap::io {

/// Detector settings read from a config file.
struct DetectorConfig {
    DetectorParams params;
    /// [m] height of the robot frame origin above the floor it stands on (floor_z = -height).
    /// Absent: the detector estimates the floor from the cloud (CLI --robot-height overrides).
    std::optional<double> robot_height_m;
};

/// Reads `section` (default "detector"). Keys that are missing keep their defaults; a key whose value
/// is not a number/boolean, or out of range, throws std::invalid_argument naming "[section] key".
/// The resulting parameters are validated (DetectorParams::validate()).
DetectorConfig loadDetectorConfig(const mrpt::config::CConfigFileBase& cfg,
                                  const std::string& section = "detector");

}  // namespace stairmap::io
