// readCloudFile: file checks, extension dispatch and the "<path>: " prefix on reader errors.

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileFormat.h"
#include "io/cloud/GunzipStream.h"
#include "io/rawlog/RawlogCloud.h"

namespace stairmap::io {

namespace {

/// Throws unless `path` is an existing, non-empty regular file.
void checkReadableFile(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw std::runtime_error(path + ": file does not exist");
    if (!fs::is_regular_file(status)) throw std::runtime_error(path + ": not a regular file");
    const auto size = fs::file_size(path, ec);
    if (ec) throw std::runtime_error(path + ": cannot determine the file size (" + ec.message() + ")");
    if (size == 0) throw std::runtime_error(path + ": file is empty");
}

PointCloud readFormat(std::istream& in, CloudFileFormat format) {
    switch (format) {
        case CloudFileFormat::Xyz: return readXyz(in);
        case CloudFileFormat::Pcd: return readPcd(in);
        default: return readPly(in);
    }
}

/// .pcd.gz etc.: inflated while it is parsed (never whole in memory), within the gzip budget.
PointCloud readGzipped(std::istream& in, CloudFileFormat format) {
    GunzipStream plain(in, kMaxGunzipCloudBytes);
    PointCloud cloud;
    try {
        cloud = readFormat(plain, format);
    } catch (const std::runtime_error&) {
        // The reader saw the data end early: the gzip problem behind it is the real error.
        if (!plain.error().empty()) throw std::runtime_error(plain.error());
        throw;
    }
    plain.finish();  // the rest must inflate cleanly (CRC, no trailing data)
    return cloud;
}

PointCloud readStreamFormat(const std::string& path, CloudFileFormat format) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot be opened for reading");
    try {
        if (!isGzippedCloudPath(path)) return readFormat(in, format);
        return readGzipped(in, format);
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace

PointCloud readCloudFile(const std::string& path) {
    const CloudFileFormat format = cloudFileFormatOf(path);
    if (format == CloudFileFormat::Unknown) {
        throw std::runtime_error(path + ": unknown point-cloud file extension (expected .xyz, .pcd, "
                                        ".ply (each optionally .gz) or .rawlog)");
    }
    checkReadableFile(path);
    if (format == CloudFileFormat::Rawlog) return readRawlogCloud(path);
    return readStreamFormat(path, format);
}

}  // namespace stairmap::io
