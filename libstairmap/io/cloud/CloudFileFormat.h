#pragma once
// Which point-cloud format a path names, from its extension (internal to io/).

#include <string>

#include "io/cloud/CloudFileParsing.h"

namespace stairmap::io {

enum class CloudFileFormat { Xyz, Pcd, Ply, Rawlog, Unknown };

/// Case-insensitive: .xyz, .pcd, .ply (each also gzipped: .xyz.gz, .pcd.gz, .ply.gz), .rawlog
/// (also .rawlog.gz).
CloudFileFormat cloudFileFormatOf(const std::string& path);

/// True for .xyz.gz, .pcd.gz and .ply.gz: the file is one gzip member holding that format (a
/// gzipped rawlog is not included: MRPT reads those itself).
bool isGzippedCloudPath(const std::string& path);

}  // namespace stairmap::io
