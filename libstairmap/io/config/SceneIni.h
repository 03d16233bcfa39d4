#pragma once
// Scene INI files (config/scenes/*.ini) -> SimulationConfig. Keys are documented in
// docs/simulator.md. Every error names the file, the [section] and the key.

#include <string>

#include "sim/SimulationConfig.h"

namespace stairmap::io {

/// Loads and builds the scene. Throws std::runtime_error "<file>: [section] key: problem"; a
/// malformed line, or a section or key that the scene's type does not read, throws
/// "<file>:<line>: ..." listing the valid sections or keys (IniKeys.h).
sim::SimulationConfig loadSimulationConfig(const std::string& path);

}  // namespace stairmap::io
