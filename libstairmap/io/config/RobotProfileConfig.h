#pragma once
// Loading a robot profile (export/RobotProfile.h) from the [robot] section of an INI file
// (config/robots/*.ini documents every key). Missing keys keep the defaults.

#include <string>

#include "export/RobotProfile.h"

namespace stairmap::io {

/// Reads `path`; the profile's name is the file stem unless [robot] name is set. A missing file,
/// a missing [robot] section, an unknown key in it, a malformed or out-of-range value (e.g. a
/// negative limit) throws std::runtime_error "<path>: [robot] <key>: <problem>".
exporting::RobotProfile loadRobotProfile(const std::string& path);

}  // namespace stairmap::io
