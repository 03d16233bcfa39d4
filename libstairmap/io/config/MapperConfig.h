#pragma once
// Loading the mapping pipeline's parameters from an MRPT-style INI file: the mapper's own sections
// [sensor], [map], [scheduling] plus the detector's [detector] and the landmarks' [landmarks]
// (loaded by their owners' loaders). Missing keys keep their documented defaults.

#include <mrpt/config/CConfigFileBase.h>

#include <string>

#include "pipeline/MapperParams.h"

namespace stairmap::io {

/// Reads [sensor]. A value that is not a number/boolean or out of range throws
/// std::invalid_argument naming "[sensor] key". robot_height_m falls back to [detector]
/// robot_height_m when [sensor] does not set it.
pipeline::SensorParams loadSensorParams(const mrpt::config::CConfigFileBase& cfg);
/// Reads [map]: resolution_m, insertion_mode (endpoints | raycast), max_range_m,
/// insert_every_n_scans.
map::VoxelMapParams loadVoxelMapParams(const mrpt::config::CConfigFileBase& cfg);
/// Reads [scheduling].
pipeline::SchedulingParams loadSchedulingParams(const mrpt::config::CConfigFileBase& cfg);

/// Everything the mapper needs: the three sections above plus [detector] and [landmarks].
pipeline::MapperParams loadMapperParams(const mrpt::config::CConfigFileBase& cfg);
/// Same from a file path, opened strictly (ConfigFile.h: a missing file, malformed line or unknown
/// section/key throws naming the path and line); value errors are prefixed with the path.
pipeline::MapperParams loadMapperParams(const std::string& ini_path);

}  // namespace stairmap::io
