// PCD (Point Cloud Library format v0.7) writer: FIELDS x y z as float32, unorganised (HEIGHT 1).

#include <ostream>
#include <string>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileParsing.h"

namespace stairmap::io {

void writePcd(std::ostream& out, const PointCloud& cloud, CloudFileEncoding encoding) {
    const std::string n = std::to_string(cloud.size());
    const bool binary = encoding == CloudFileEncoding::Binary;
    out << "# .PCD v0.7 - Point Cloud Data file format (written by stairmap)\n"
        << "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
        << "WIDTH " << n << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << n << "\n"
        << "DATA " << (binary ? "binary" : "ascii") << "\n";
    if (binary) {
        detail::writeBinaryPoints(out, cloud);
    } else {
        for (const Eigen::Vector3f& p : cloud) detail::writeAsciiPoint(out, p);
    }
    detail::checkWritten(out);
}

}  // namespace stairmap::io
