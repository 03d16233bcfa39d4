#pragma once
// Parsed header of a PLY file (internal to io/). Format: Greg Turk's PLY polygon file format.

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace stairmap::io::detail {

/// A scalar PLY type as (kind, size): kind 'I' signed, 'U' unsigned, 'F' floating point.
struct PlyScalar {
    char kind = 'F';
    std::size_t size = 4;  ///< [bytes]
};

struct PlyProperty {
    std::string name;
    PlyScalar value;        ///< the scalar type, or the item type of a list
    bool is_list = false;
    PlyScalar list_count;   ///< type of a list's length prefix
};

struct PlyElement {
    std::string name;
    std::size_t count = 0;
    std::vector<PlyProperty> properties;
};

enum class PlyEncoding { Ascii, BinaryLittleEndian };

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    std::size_t vertex_element = 0;        ///< index of "vertex" in elements
    std::size_t xyz_property[3] = {0, 0, 0};  ///< indices of x, y, z among its properties
};

/// Reads header lines up to and including end_header; the stream is left at the first data byte.
/// Throws std::runtime_error("bad PLY header: ...") on anything malformed or unsupported.
PlyHeader readPlyHeader(std::istream& in);

}  // namespace stairmap::io::detail
