#pragma once
// sensor_msgs/PointCloud2 -> points, independent of DDS (the layout and bytes are handed over).
// Any layout with x, y, z fields of type FLOAT32 (or FLOAT64) at any offsets and point_step;
// organised (height > 1) or not; big-endian data are byte-swapped (is_bigendian honoured).
// Non-finite points (NaN padding of organised clouds) are dropped and counted. A cloud without
// x/y/z, with fields outside the point, rows shorter than their points, less data than the
// layout needs, or more points than the limit is refused with a reason; nothing is read out of
// bounds whatever the header says.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap::ros2 {

/// sensor_msgs/PointField datatype codes.
enum PointFieldType : std::uint8_t {
    kInt8 = 1, kUint8 = 2, kInt16 = 3, kUint16 = 4, kInt32 = 5, kUint32 = 6, kFloat32 = 7, kFloat64 = 8
};

struct CloudField {
    std::string name;
    std::uint32_t offset = 0;    ///< [bytes] from the start of the point
    std::uint8_t datatype = 0;   ///< PointFieldType
    std::uint32_t count = 1;     ///< elements
};

/// The PointCloud2 header fields that describe the data.
struct CloudLayout {
    std::uint32_t height = 1;      ///< rows (1: unorganised)
    std::uint32_t width = 0;       ///< points per row
    std::uint32_t point_step = 0;  ///< [bytes] per point
    std::uint32_t row_step = 0;    ///< [bytes] per row
    bool is_bigendian = false;
    std::vector<CloudField> fields;
};

struct CloudDecodeLimits {
    std::size_t max_points = 4'000'000;  ///< [-] more points (width x height) than this: refused
};

enum class CloudDecodeStatus {
    Ok,
    NoXyz,      ///< no x, y and z fields of a float type
    Malformed,  ///< inconsistent sizes, truncated data, too many points
};

struct CloudDecodeResult {
    CloudDecodeStatus status = CloudDecodeStatus::Ok;
    std::string problem;                ///< why not Ok, e.g. "data has 100 bytes, layout needs 160"
    PointCloud points;                  ///< [m] in the cloud's own frame, finite points only
    std::size_t dropped_non_finite = 0; ///< points dropped for NaN/Inf coordinates
};

/// Decodes `size` bytes at `data` laid out as `layout`. Never throws for bad input (only
/// std::bad_alloc). Cost: linear in width x height.
CloudDecodeResult decodePointCloud(const CloudLayout& layout, const std::uint8_t* data,
                                   std::size_t size, const CloudDecodeLimits& limits = {});

}  // namespace stairmap::ros2
