#pragma once
// Loading LandmarkParams from MRPT-style INI sections [landmarks] and [floors]
// (documented in config/default.ini). Missing keys keep the defaults of map/LandmarkParams.h.

#include <mrpt/config/CConfigFileBase.h>

#include <string>

#include "map/LandmarkParams.h"

namespace stairmap::io {

/// Reads the association/fusion keys from `landmarks_section` and the floor keys from
/// `floors_section`. A value that is not a number/boolean, or out of range, throws
/// std::invalid_argument naming "[section] key" and the problem.
LandmarkParams loadLandmarkParams(const mrpt::config::CConfigFileBase& cfg,
                                  const std::string& landmarks_section = "landmarks",
                                  const std::string& floors_section = "floors");

}  // namespace stairmap::io
