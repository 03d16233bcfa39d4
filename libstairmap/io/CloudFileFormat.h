#pragma once
// Which point-cloud format a path names, from its extension (internal to io/).

#include <string>

#include "io/CloudFileParsing.h"

namespace stairmap::io {

enum class CloudFileFormat { Xyz, Pcd, Ply, Rawlog, Unknown };

/// Case-insensitive: .xyz, .pcd, .ply, .rawlog (also .rawlog.gz).
CloudFileFormat cloudFileFormatOf(const std::string& path);

}  // namespace stairmap::io
