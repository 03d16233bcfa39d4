// PCD reader: DATA ascii and binary, any FIELDS that include x y z (extra fields are skipped).

#include <algorithm>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileParsing.h"
#include "io/cloud/PcdHeader.h"

namespace stairmap::io {

namespace {

using detail::PcdHeader;

PointCloud readPcdAscii(std::istream& in, const PcdHeader& h) {
    detail::PointCollector points(h.num_points);
    std::string line;
    std::size_t n = 0;
    while (detail::readLine(in, line)) {
        const auto words = detail::splitWords(line);
        if (words.empty()) continue;
        if (n == h.num_points) {
            throw std::runtime_error("more point lines than the header's POINTS " + std::to_string(h.num_points));
        }
        if (words.size() != h.point_columns) {
            throw std::runtime_error("point " + std::to_string(n) + ": expected " + std::to_string(h.point_columns) +
                                     " values, found " + std::to_string(words.size()));
        }
        double xyz[3];
        for (int k = 0; k < 3; ++k) {
            const std::string_view word = words[h.fields[h.xyz_field[k]].column];
            if (!detail::parseNumber(word, xyz[k])) {
                throw std::runtime_error("point " + std::to_string(n) + ": '" + std::string(word.substr(0, 40)) +
                                         "' is not a number");
            }
        }
        points.add(xyz[0], xyz[1], xyz[2]);
        ++n;
    }
    if (n < h.num_points) {
        throw std::runtime_error("header declares " + std::to_string(h.num_points) + " points but the data has " +
                                 std::to_string(n));
    }
    return points.finish();
}

/// Before allocating anything for them: the declared points must fit in the bytes that follow.
void checkBinarySize(std::istream& in, const PcdHeader& h) {
    const std::size_t left = detail::bytesLeft(in);
    if (h.num_points > left / h.point_bytes) {
        throw std::runtime_error("truncated binary data: header declares " + std::to_string(h.num_points) +
                                 " points of " + std::to_string(h.point_bytes) + " bytes, the file holds " +
                                 std::to_string(left) + " bytes after the header");
    }
}

PointCloud readPcdBinary(std::istream& in, const PcdHeader& h) {
    checkBinarySize(in, h);
    detail::PointCollector points(h.num_points);
    // Chunks of about 1 MiB (at least one record) whatever the record size.
    const std::size_t kChunkPoints = std::max<std::size_t>(1, (std::size_t{1} << 20) / h.point_bytes);
    std::vector<char> buffer;
    std::size_t n = 0;
    while (n < h.num_points) {
        const std::size_t chunk = std::min(kChunkPoints, h.num_points - n);
        buffer.resize(chunk * h.point_bytes);
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        const std::size_t complete = static_cast<std::size_t>(in.gcount()) / h.point_bytes;
        for (std::size_t i = 0; i < complete; ++i) {
            const char* record = buffer.data() + i * h.point_bytes;
            double xyz[3];
            for (int k = 0; k < 3; ++k) {
                const detail::PcdField& f = h.fields[h.xyz_field[k]];
                xyz[k] = detail::decodeLittleEndian(record + f.offset, f.type, f.size);
            }
            points.add(xyz[0], xyz[1], xyz[2]);
        }
        n += complete;
        if (complete < chunk) {
            throw std::runtime_error("truncated binary data: header declares " + std::to_string(h.num_points) +
                                     " points of " + std::to_string(h.point_bytes) + " bytes, the file holds " +
                                     std::to_string(n) + " complete points");
        }
    }
    if (in.peek() != std::char_traits<char>::eof()) {
        throw std::runtime_error("data continues after the header's POINTS " + std::to_string(h.num_points) +
                                 " (wrong point count?)");
    }
    return points.finish();
}

}  // namespace

PointCloud readPcd(std::istream& in) {
    const PcdHeader header = detail::readPcdHeader(in);
    detail::checkDeclaredPoints(header.num_points);
    return header.encoding == detail::PcdEncoding::Ascii ? readPcdAscii(in, header) : readPcdBinary(in, header);
}

}  // namespace stairmap::io
