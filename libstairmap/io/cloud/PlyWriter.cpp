// PLY writer: one `vertex` element with float x y z, ascii or binary_little_endian.

#include <ostream>
#include <string>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileParsing.h"

namespace stairmap::io {

void writePly(std::ostream& out, const PointCloud& cloud, CloudFileEncoding encoding) {
    const bool binary = encoding == CloudFileEncoding::Binary;
    out << "ply\nformat " << (binary ? "binary_little_endian" : "ascii") << " 1.0\n"
        << "comment written by stairmap\n"
        << "element vertex " << cloud.size() << "\n"
        << "property float x\nproperty float y\nproperty float z\nend_header\n";
    if (binary) {
        detail::writeBinaryPoints(out, cloud);
    } else {
        for (const Eigen::Vector3f& p : cloud) detail::writeAsciiPoint(out, p);
    }
    detail::checkWritten(out);
}

}  // namespace stairmap::io
