// PLY reader: ascii and binary_little_endian; x y z of the `vertex` element (float, double or
// integer), other vertex properties and other elements (faces, ...) are skipped.

#include <algorithm>
#include <cmath>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/cloud/CloudFile.h"
#include "io/cloud/CloudFileParsing.h"
#include "io/cloud/PlyHeader.h"

namespace stairmap::io {

namespace {

using detail::PlyElement;
using detail::PlyHeader;
using detail::PlyProperty;
using detail::PlyScalar;

[[noreturn]] void truncated(const PlyElement& e, std::size_t index) {
    throw std::runtime_error("truncated data: element '" + e.name + "' declares " + std::to_string(e.count) +
                             " entries, the file ends at entry " + std::to_string(index));
}

/// Words of the next non-blank line; empty at the end of the stream.
std::vector<std::string_view> nextWords(std::istream& in, std::string& line) {
    while (detail::readLine(in, line)) {
        auto words = detail::splitWords(line);
        if (!words.empty()) return words;
    }
    return {};
}

/// Finds x y z in one ASCII vertex line, walking over scalar and list properties.
void parseAsciiVertex(const std::vector<std::string_view>& words, const PlyHeader& h, std::size_t index,
                      double xyz[3]) {
    const auto& props = h.elements[h.vertex_element].properties;
    const std::string where = "vertex " + std::to_string(index) + ": ";
    std::size_t w = 0;
    for (std::size_t p = 0; p < props.size(); ++p) {
        if (w >= words.size()) throw std::runtime_error(where + "too few values on the line");
        double value = 0.0;
        if (!detail::parseNumber(words[w], value)) {
            throw std::runtime_error(where + "'" + std::string(words[w].substr(0, 40)) + "' is not a number");
        }
        if (props[p].is_list) {
            if (!(value >= 0.0 && value <= double(words.size()))) throw std::runtime_error(where + "bad list length");
            w += 1 + static_cast<std::size_t>(value);
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            if (h.xyz_property[k] == p) xyz[k] = value;
        }
        ++w;
    }
    if (w != words.size()) throw std::runtime_error(where + "expected " + std::to_string(w) + " values, found " +
                                                    std::to_string(words.size()));
}

PointCloud readPlyAscii(std::istream& in, const PlyHeader& h) {
    std::string line;
    for (std::size_t e = 0; e < h.vertex_element; ++e) {  // elements before the vertices: one line each
        if (h.elements[e].properties.empty()) continue;  // no data at all
        for (std::size_t i = 0; i < h.elements[e].count; ++i) {
            if (nextWords(in, line).empty()) truncated(h.elements[e], i);
        }
    }
    const PlyElement& vertex = h.elements[h.vertex_element];
    detail::PointCollector points(vertex.count);
    for (std::size_t i = 0; i < vertex.count; ++i) {
        const auto words = nextWords(in, line);
        if (words.empty()) truncated(vertex, i);
        double xyz[3] = {0, 0, 0};
        parseAsciiVertex(words, h, i, xyz);
        points.add(xyz[0], xyz[1], xyz[2]);
    }
    return points.finish();
}

/// Reads one binary scalar; false at the end of the stream.
bool readScalar(std::istream& in, const PlyScalar& type, double& value) {
    char bytes[8];
    if (!detail::readExactly(in, bytes, type.size)) return false;
    value = detail::decodeLittleEndian(bytes, type.kind, type.size);
    return true;
}

/// Reads one binary element entry; stores the vertex coordinates when `xyz_index` is given.
bool readBinaryEntry(std::istream& in, const PlyElement& e, const std::size_t* xyz_index, double xyz[3]) {
    for (std::size_t p = 0; p < e.properties.size(); ++p) {
        const PlyProperty& prop = e.properties[p];
        double value = 0.0;
        if (!prop.is_list) {
            if (!readScalar(in, prop.value, value)) return false;
            for (int k = 0; xyz_index && k < 3; ++k) {
                if (xyz_index[k] == p) xyz[k] = value;
            }
            continue;
        }
        if (!readScalar(in, prop.list_count, value)) return false;
        if (!(value >= 0.0 && value < 1e9)) throw std::runtime_error("element '" + e.name + "': bad list length");
        const auto bytes = static_cast<std::streamsize>(value) * static_cast<std::streamsize>(prop.value.size);
        in.ignore(bytes);
        if (in.gcount() != bytes) return false;
    }
    return true;
}

/// Fast path for vertices without list properties: fixed-size records read in chunks.
PointCloud readFixedSizeVertices(std::istream& in, const PlyElement& vertex, const std::size_t xyz_index[3]) {
    std::size_t record_bytes = 0, offsets[3] = {0, 0, 0};
    for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
        for (int k = 0; k < 3; ++k) {
            if (xyz_index[k] == p) offsets[k] = record_bytes;
        }
        record_bytes += vertex.properties[p].value.size;
    }
    const std::size_t left = detail::bytesLeft(in);  // checked before anything is allocated
    if (record_bytes == 0 || vertex.count > left / record_bytes) {
        throw std::runtime_error("truncated data: element 'vertex' declares " + std::to_string(vertex.count) +
                                 " entries of " + std::to_string(record_bytes) + " bytes, the file holds " +
                                 std::to_string(left) + " bytes for them");
    }
    detail::PointCollector points(vertex.count);
    const std::size_t kChunk = std::max<std::size_t>(1, (std::size_t{1} << 20) / record_bytes);
    std::vector<char> buffer;
    for (std::size_t done = 0; done < vertex.count;) {
        const std::size_t chunk = std::min(kChunk, vertex.count - done);
        buffer.resize(chunk * record_bytes);
        in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
        const std::size_t complete = static_cast<std::size_t>(in.gcount()) / record_bytes;
        for (std::size_t i = 0; i < complete; ++i) {
            const char* record = buffer.data() + i * record_bytes;
            double xyz[3];
            for (int k = 0; k < 3; ++k) {
                const PlyScalar& type = vertex.properties[xyz_index[k]].value;
                xyz[k] = detail::decodeLittleEndian(record + offsets[k], type.kind, type.size);
            }
            points.add(xyz[0], xyz[1], xyz[2]);
        }
        done += complete;
        if (complete < chunk) truncated(vertex, done);
    }
    return points.finish();
}

PointCloud readPlyBinary(std::istream& in, const PlyHeader& h) {
    double unused[3];
    for (std::size_t e = 0; e < h.vertex_element; ++e) {
        if (h.elements[e].properties.empty()) continue;  // no data at all, whatever its count
        for (std::size_t i = 0; i < h.elements[e].count; ++i) {
            if (!readBinaryEntry(in, h.elements[e], nullptr, unused)) truncated(h.elements[e], i);
        }
    }
    const PlyElement& vertex = h.elements[h.vertex_element];
    bool has_list = false;
    for (const PlyProperty& p : vertex.properties) has_list = has_list || p.is_list;
    if (!has_list) return readFixedSizeVertices(in, vertex, h.xyz_property);
    detail::PointCollector points(vertex.count);
    for (std::size_t i = 0; i < vertex.count; ++i) {
        double xyz[3] = {0, 0, 0};
        if (!readBinaryEntry(in, vertex, h.xyz_property, xyz)) truncated(vertex, i);
        points.add(xyz[0], xyz[1], xyz[2]);
    }
    return points.finish();
}

}  // namespace

PointCloud readPly(std::istream& in) {
    const PlyHeader header = detail::readPlyHeader(in);
    detail::checkDeclaredPoints(header.elements[header.vertex_element].count);
    return header.encoding == detail::PlyEncoding::Ascii ? readPlyAscii(in, header) : readPlyBinary(in, header);
}

}  // namespace stairmap::io
