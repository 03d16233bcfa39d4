#pragma once
// Parsed header of a PCD file (internal to io/). Format: pointclouds.org "The PCD file format".

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace stairmap::io::detail {

struct PcdField {
    std::string name;
    std::size_t size = 4;    ///< [bytes] per element: 1, 2, 4 or 8
    char type = 'F';         ///< 'I' signed, 'U' unsigned, 'F' floating point
    std::size_t count = 1;   ///< elements per point
    std::size_t offset = 0;  ///< [bytes] from the start of a binary point record
    std::size_t column = 0;  ///< index of the first element among the words of an ASCII line
};

enum class PcdEncoding { Ascii, Binary };

struct PcdHeader {
    std::vector<PcdField> fields;
    std::size_t num_points = 0;
    std::size_t point_bytes = 0;    ///< size of one binary point record
    std::size_t point_columns = 0;  ///< words per ASCII point line
    std::size_t xyz_field[3] = {0, 0, 0};  ///< indices into fields of x, y, z
    PcdEncoding encoding = PcdEncoding::Ascii;
};

/// Reads header lines up to and including DATA; the stream is left at the first data byte.
/// Throws std::runtime_error("bad PCD header: ...") on anything malformed or unsupported.
PcdHeader readPcdHeader(std::istream& in);

}  // namespace stairmap::io::detail
