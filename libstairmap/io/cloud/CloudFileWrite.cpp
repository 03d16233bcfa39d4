// writeCloudFile: extension dispatch and the file wrapper around the stream writers.

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileFormat.h"
#include "io/cloud/GzipBuffer.h"

namespace stairmap::io {

namespace {
void writeFormat(std::ostream& out, const PointCloud& cloud, CloudFileFormat format,
                 CloudFileEncoding encoding) {
    switch (format) {
        case CloudFileFormat::Xyz: writeXyz(out, cloud); break;
        case CloudFileFormat::Pcd: writePcd(out, cloud, encoding); break;
        default: writePly(out, cloud, encoding); break;
    }
}
}  // namespace

void writeCloudFile(const std::string& path, const PointCloud& cloud, CloudFileEncoding encoding) {
    const CloudFileFormat format = cloudFileFormatOf(path);
    if (format == CloudFileFormat::Rawlog || format == CloudFileFormat::Unknown) {
        throw std::runtime_error(path + ": cannot write this format (expected .xyz, .pcd or .ply, "
                                        "each optionally .gz)");
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot be opened for writing");
    try {
        if (isGzippedCloudPath(path)) {
            std::ostringstream plain(std::ios::binary);
            writeFormat(plain, cloud, format, encoding);
            out << gzipBuffer(plain.str());
        } else {
            writeFormat(out, cloud, format, encoding);
        }
        out.flush();
        detail::checkWritten(out);
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace stairmap::io
