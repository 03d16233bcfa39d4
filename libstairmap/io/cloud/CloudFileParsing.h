#pragma once
// Small helpers shared by the XYZ, PCD and PLY readers/writers (internal to io/).

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap::io::detail {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "binary PCD/PLY I/O assumes a little-endian host");

/// Splits a line at blanks (spaces, tabs, CR).
std::vector<std::string_view> splitWords(std::string_view line);

/// Parses a whole token as a number (accepts a leading '+', "nan", "inf"). False on any junk.
bool parseNumber(std::string_view token, double& value);

/// Parses a whole token as a non-negative integer. False on junk or overflow.
bool parseCount(std::string_view token, std::size_t& value);

/// Reads one line (without its '\n') like std::getline, but throws "line N bytes long..." past
/// kMaxCloudLineBytes (a file without line breaks must not become one huge string).
bool readLine(std::istream& in, std::string& line);

/// Bytes between the stream position and its end, for streams that can tell (files, strings);
/// otherwise (a gzip stream) kMaxGunzipCloudBytes, the most such a stream can deliver.
std::size_t bytesLeft(std::istream& in);

/// Collects points, dropping non-finite ones, and remembers whether any point was seen at all.
class PointCollector {
public:
    /// `expected`: the declared count, a hint for the first allocation (capped, never trusted).
    explicit PointCollector(std::size_t expected = 0);
    /// Throws "more than kMaxCloudPoints points" past the limit.
    void add(double x, double y, double z);
    /// Throws "contains no finite points (N points read)" if points were read but none was finite.
    PointCloud finish();

private:
    PointCloud cloud_;
    std::size_t num_read_ = 0;
};

/// Throws "declares N points, more than the limit of kMaxCloudPoints" if `declared` is larger.
void checkDeclaredPoints(std::size_t declared);

/// Decodes one little-endian value: type 'I' signed / 'U' unsigned (size 1, 2, 4, 8) or
/// 'F' floating point (size 4, 8).
double decodeLittleEndian(const char* bytes, char type, std::size_t size);

/// Reads exactly n bytes; false if the stream ends first.
bool readExactly(std::istream& in, char* buffer, std::size_t n);

/// Writes "x y z\n" with enough digits for float values to round-trip.
void writeAsciiPoint(std::ostream& out, const Eigen::Vector3f& p);

/// Writes the cloud as packed little-endian float32 x y z triples.
void writeBinaryPoints(std::ostream& out, const PointCloud& cloud);

/// Throws std::runtime_error(message) unless the stream is still good (used after writing).
void checkWritten(const std::ostream& out);

}  // namespace stairmap::io::detail
