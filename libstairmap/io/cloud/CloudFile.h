#pragma once
// Point-cloud files: XYZ, PCD, PLY (read and write) and MRPT rawlogs holding one 3D observation (read).
//
// Frames: files hold points in whatever frame their writer used; `stairmap detect` expects the
// gravity-aligned robot frame (x forward, y left, z up) [m]. A rawlog observation is converted to
// the robot frame through its sensorPose.
//
// Errors: every reader throws std::runtime_error on bad input (bad header, truncated or missing data,
// wrong point counts, text in numeric fields, unsupported encodings, no finite point at all). The
// stream functions say what is wrong; the path functions prefix the message with "<path>: ".
// Non-finite points (NaN/Inf in x, y or z) are dropped on read. A file that declares zero points
// gives an empty cloud (not an error); a zero-byte file is an error.
// Cost: linear in the file size; binary formats are read in one pass without extra copies.
//
// Memory budget (hostile files, docs/detect-io.md): a cloud holds at most kMaxCloudPoints points
// (12 bytes each in memory); a gzipped file is inflated while it is parsed, never as a whole, and
// may decompress to at most kMaxGunzipCloudBytes; text lines are at most kMaxCloudLineBytes long;
// a binary header's declared data must fit in the bytes that follow it (checked before anything
// is allocated for it); a PCD point record is at most kMaxPcdPointBytes. Past any limit the reader
// throws, naming the limit.

#include <cstddef>
#include <iosfwd>
#include <string>

#include "core/PointCloud.h"

namespace stairmap::io {

constexpr std::size_t kMaxCloudPoints = 4'000'000;            ///< points per cloud file
constexpr std::size_t kMaxGunzipCloudBytes = std::size_t{256} << 20;  ///< [bytes] inflated .gz data
constexpr std::size_t kMaxCloudLineBytes = std::size_t{1} << 20;   ///< [bytes] one text line
constexpr std::size_t kMaxPcdPointBytes = std::size_t{1} << 20;    ///< [bytes] one PCD point record

enum class CloudFileEncoding {
    Ascii,   ///< human-readable text
    Binary,  ///< little-endian binary (PCD `DATA binary`, PLY `binary_little_endian`)
};

/// Reads a cloud, choosing the format by the (case-insensitive) extension:
///   .xyz    ASCII "x y z" per line; extra columns ignored; '#' comments and blank lines skipped.
///   .pcd    DATA ascii or binary (binary_compressed is rejected); any FIELDS containing x y z.
///   .ply    ascii or binary_little_endian (big-endian rejected); the `vertex` element's x y z.
///   .xyz.gz, .pcd.gz, .ply.gz  one gzip member holding that format (inflated in memory, then
///           parsed as above; a plain, truncated or corrupt gzip stream is an error).
///   .rawlog MRPT rawlog (plain or gzipped) holding 3D observations: the FIRST observation that
///           converts to points is used (later ones are ignored), in the robot frame.
/// Throws std::runtime_error("<path>: <problem>") on a missing/unreadable/malformed file.
PointCloud readCloudFile(const std::string& path);

/// Writes `.xyz`, `.pcd` or `.ply` (chosen by extension; a further `.gz` gzips the file
/// reproducibly, see io/cloud/GzipBuffer.h) with float32 coordinates. XYZ is always
/// ASCII (the format has no binary variant). ASCII output uses 9 significant digits, so float
/// values round-trip exactly. Throws std::runtime_error("<path>: <problem>") if the extension is
/// unknown or the file cannot be written.
void writeCloudFile(const std::string& path, const PointCloud& cloud,
                    CloudFileEncoding encoding = CloudFileEncoding::Binary);

// Stream functions (open binary streams for binary encodings). Errors carry no path.
PointCloud readXyz(std::istream& in);
PointCloud readPcd(std::istream& in);
PointCloud readPly(std::istream& in);
void writeXyz(std::ostream& out, const PointCloud& cloud);
void writePcd(std::ostream& out, const PointCloud& cloud, CloudFileEncoding encoding);
void writePly(std::ostream& out, const PointCloud& cloud, CloudFileEncoding encoding);

}  // namespace stairmap::io
