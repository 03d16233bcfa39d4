#include "ros2/PointCloudDecoder.h"

#include <cmath>
#include <cstring>

namespace stairmap::ros2 {
namespace {

/// Where one coordinate is inside a point.
struct Coordinate {
    std::uint32_t offset = 0;
    bool is_double = false;
};

bool isHostBigEndian() {
    const std::uint16_t probe = 1;
    std::uint8_t first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 0;
}

/// Reads a float or double at `p`, swapping bytes when the data's byte order is not the host's.
double readCoordinate(const std::uint8_t* p, const Coordinate& c, bool swap) {
    std::uint8_t bytes[8];
    const std::size_t n = c.is_double ? 8 : 4;
    for (std::size_t i = 0; i < n; ++i) bytes[i] = swap ? p[n - 1 - i] : p[i];
    if (c.is_double) {
        double v;
        std::memcpy(&v, bytes, 8);
        return v;
    }
    float v;
    std::memcpy(&v, bytes, 4);
    return v;
}

/// Finds field `name` (float32/float64, count >= 1) lying inside the point; problem on failure.
bool findCoordinate(const CloudLayout& layout, const char* name, Coordinate& out, std::string& problem) {
    for (const CloudField& f : layout.fields) {
        if (f.name != name) continue;
        if (f.datatype != kFloat32 && f.datatype != kFloat64) {
            problem = std::string("field ") + name + " has datatype " + std::to_string(f.datatype) +
                      ", not FLOAT32 (7) or FLOAT64 (8)";
            return false;
        }
        out.is_double = f.datatype == kFloat64;
        out.offset = f.offset;
        const std::uint64_t end = std::uint64_t(f.offset) + (out.is_double ? 8 : 4);
        if (f.count == 0 || end > layout.point_step) {
            problem = std::string("field ") + name + " (offset " + std::to_string(f.offset) +
                      ") does not fit in point_step " + std::to_string(layout.point_step);
            return false;
        }
        return true;
    }
    problem = std::string("no field named ") + name;
    return false;
}

/// Checks the sizes; returns an empty string when the layout can be read from `size` bytes.
std::string checkSizes(const CloudLayout& layout, std::size_t size, const CloudDecodeLimits& limits) {
    const std::uint64_t points = std::uint64_t(layout.width) * layout.height;
    if (points > limits.max_points)
        return std::to_string(layout.width) + " x " + std::to_string(layout.height) +
               " points exceed the limit of " + std::to_string(limits.max_points);
    if (points == 0) return "";
    const std::uint64_t row_bytes = std::uint64_t(layout.width) * layout.point_step;
    if (layout.row_step < row_bytes)
        return "row_step " + std::to_string(layout.row_step) + " is less than width x point_step " +
               std::to_string(row_bytes);
    const std::uint64_t needed = std::uint64_t(layout.height - 1) * layout.row_step + row_bytes;
    if (needed > size)
        return "data has " + std::to_string(size) + " bytes, the layout needs " + std::to_string(needed);
    return "";
}

}  // namespace

CloudDecodeResult decodePointCloud(const CloudLayout& layout, const std::uint8_t* data,
                                   std::size_t size, const CloudDecodeLimits& limits) {
    CloudDecodeResult result;
    Coordinate x, y, z;
    if (!findCoordinate(layout, "x", x, result.problem) ||
        !findCoordinate(layout, "y", y, result.problem) ||
        !findCoordinate(layout, "z", z, result.problem)) {
        result.status = CloudDecodeStatus::NoXyz;
        return result;
    }
    result.problem = checkSizes(layout, size, limits);
    if (!result.problem.empty() || (data == nullptr && size > 0)) {
        result.status = CloudDecodeStatus::Malformed;
        if (result.problem.empty()) result.problem = "no data";
        return result;
    }
    const bool swap = layout.is_bigendian != isHostBigEndian();
    result.points.reserve(std::size_t(layout.width) * layout.height);
    for (std::uint32_t row = 0; row < layout.height; ++row) {
        const std::uint8_t* row_start = data + std::size_t(row) * layout.row_step;
        for (std::uint32_t col = 0; col < layout.width; ++col) {
            const std::uint8_t* p = row_start + std::size_t(col) * layout.point_step;
            const double px = readCoordinate(p + x.offset, x, swap);
            const double py = readCoordinate(p + y.offset, y, swap);
            const double pz = readCoordinate(p + z.offset, z, swap);
            // beyond 1e9 m is garbage, and would overflow the float conversion
            if (!(std::fabs(px) < 1e9 && std::fabs(py) < 1e9 && std::fabs(pz) < 1e9)) {
                ++result.dropped_non_finite;
                continue;
            }
            result.points.emplace_back(float(px), float(py), float(pz));
        }
    }
    return result;
}

}  // namespace stairmap::ros2
