#pragma once
// Opening MRPT-style INI files safely: MRPT reads a missing file as an empty config, we refuse it.

#include <mrpt/config/CConfigFile.h>

#include <memory>
#include <string>

namespace stairmap::io {

/// Opens an existing INI file. Throws std::runtime_error naming the path if it does not exist or
/// cannot be read.
std::unique_ptr<mrpt::config::CConfigFile> openIniFile(const std::string& path);

}  // namespace stairmap::io
