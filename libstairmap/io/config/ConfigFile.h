#pragma once
// The stairmap configuration file (config/default.ini and the presets): one INI file holding the
// sections of every loader — [sensor] [map] [scheduling] (MapperConfig), [detector]
// (DetectorConfig), [landmarks] [floors] (LandmarkConfig). `detect` and `eval` read only
// [detector] but accept the same files. Opening is strict: a malformed line, or a section or key
// none of the loaders reads, is an error naming the file and line (MRPT would ignore it).

#include <mrpt/config/CConfigFile.h>

#include <memory>
#include <string>

#include "io/config/DetectorConfig.h"
#include "io/config/IniKeys.h"

namespace stairmap::io {

/// Every section and key the loaders read, learnt once by running loadMapperParams on an empty
/// config through a KeyRecorder.
const IniKeys& configFileKeys();

/// Opens a configuration file after checking it line by line (IniSyntax.h) and against
/// configFileKeys(). Throws std::runtime_error naming the path (and line, section and key).
std::unique_ptr<mrpt::config::CConfigFile> openConfigFile(const std::string& path);

/// [detector] of a configuration file, checked as openConfigFile; value errors are prefixed
/// with the path.
DetectorConfig loadDetectorConfigFile(const std::string& path);

}  // namespace stairmap::io
