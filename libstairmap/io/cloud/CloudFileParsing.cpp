#include "io/cloud/CloudFileParsing.h"

#include "io/cloud/CloudFile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <streambuf>

namespace stairmap::io::detail {

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    const auto is_blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; };
    while (i < line.size()) {
        while (i < line.size() && is_blank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i])) ++i;
        if (i > start) words.push_back(line.substr(start, i - start));
    }
    return words;
}

bool parseNumber(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    if (token.empty()) return false;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    // Out-of-range values (e.g. 1e999) are not finite points: map them to infinity, not an error.
    if (ec == std::errc::result_out_of_range && ptr == end) {
        value = token.front() == '-' ? -INFINITY : INFINITY;
        return true;
    }
    return ec == std::errc() && ptr == end;
}

bool parseCount(std::string_view token, std::size_t& value) {
    if (token.empty()) return false;
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    return ec == std::errc() && ptr == end;
}

bool readLine(std::istream& in, std::string& line) {
    line.clear();
    std::streambuf* buf = in.rdbuf();
    constexpr int kEof = std::char_traits<char>::eof();
    for (int c = buf->sbumpc(); c != '\n'; c = buf->sbumpc()) {
        if (c == kEof) {
            in.setstate(std::ios::eofbit);
            if (line.empty()) in.setstate(std::ios::failbit);
            return !line.empty();
        }
        if (line.size() == kMaxCloudLineBytes) {
            throw std::runtime_error("a line is longer than " + std::to_string(kMaxCloudLineBytes) +
                                     " bytes (not a text cloud, or no line breaks)");
        }
        line.push_back(static_cast<char>(c));
    }
    return true;
}

std::size_t bytesLeft(std::istream& in) {
    const std::istream::pos_type here = in.tellg();
    if (here == std::istream::pos_type(-1)) {
        in.clear(in.rdstate() & ~std::ios::failbit);
        return kMaxGunzipCloudBytes;
    }
    in.seekg(0, std::ios::end);
    const std::istream::pos_type end = in.tellg();
    in.seekg(here);
    return end >= here ? static_cast<std::size_t>(end - here) : 0;
}

void checkDeclaredPoints(std::size_t declared) {
    if (declared > kMaxCloudPoints) {
        throw std::runtime_error("header declares " + std::to_string(declared) +
                                 " points, more than the limit of " + std::to_string(kMaxCloudPoints) +
                                 " points per cloud file (downsample the cloud)");
    }
}

PointCollector::PointCollector(std::size_t expected) {
    // Never trust a header's count for allocation: a corrupt header must not exhaust memory.
    cloud_.reserve(std::min<std::size_t>(expected, std::size_t{1} << 20));
}

void PointCollector::add(double x, double y, double z) {
    if (num_read_ == kMaxCloudPoints) {
        throw std::runtime_error("more than " + std::to_string(kMaxCloudPoints) +
                                 " points, the limit of a cloud file (downsample the cloud)");
    }
    ++num_read_;
    const Eigen::Vector3f p(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
    if (p.allFinite()) cloud_.push_back(p);
}

PointCloud PointCollector::finish() {
    if (num_read_ > 0 && cloud_.empty()) {
        throw std::runtime_error("contains no finite points (" + std::to_string(num_read_) +
                                 " points read, all NaN/Inf)");
    }
    return std::move(cloud_);
}

bool readExactly(std::istream& in, char* buffer, std::size_t n) {
    in.read(buffer, static_cast<std::streamsize>(n));
    return static_cast<std::size_t>(in.gcount()) == n;
}

void writeAsciiPoint(std::ostream& out, const Eigen::Vector3f& p) {
    char line[96];
    // %.9g: 9 significant digits make every float round-trip; snprintf ignores the stream locale.
    const int n = std::snprintf(line, sizeof(line), "%.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    out.write(line, n);
}

void writeBinaryPoints(std::ostream& out, const PointCloud& cloud) {
    for (const Eigen::Vector3f& p : cloud) {
        const float xyz[3] = {p.x(), p.y(), p.z()};
        out.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
    }
}

void checkWritten(const std::ostream& out) {
    if (!out.good()) throw std::runtime_error("write failed (disk full or I/O error?)");
}

double decodeLittleEndian(const char* bytes, char type, std::size_t size) {
    // memcpy avoids unaligned reads; the host is little-endian like PCD/PLY binary data.
    auto as = [bytes](auto value) { std::memcpy(&value, bytes, sizeof(value)); return static_cast<double>(value); };
    if (type == 'F') return size == 4 ? as(float{}) : as(double{});
    if (type == 'I') {
        switch (size) {
            case 1: return as(std::int8_t{});
            case 2: return as(std::int16_t{});
            case 4: return as(std::int32_t{});
            default: return as(std::int64_t{});
        }
    }
    switch (size) {
        case 1: return as(std::uint8_t{});
        case 2: return as(std::uint16_t{});
        case 4: return as(std::uint32_t{});
        default: return as(std::uint64_t{});
    }
}

}  // namespace stairmap::io::detail
