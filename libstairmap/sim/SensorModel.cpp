#include "sim/SensorModel.h"

#include <cmath>
#include <stdexcept>

namespace stairmap::sim {

namespace {
constexpr double kDeg = M_PI / 180.0;

std::vector<double> evenlySpaced(double from, double to, int count) {
    std::vector<double> values(count);
    for (int i = 0; i < count; ++i) values[i] = from + (to - from) * i / (count - 1);
    return values;
}
}  // namespace

SensorParams vlp16() {
    SensorParams p;
    p.model = "vlp16";
    p.elevations_deg = evenlySpaced(-15.0, 15.0, 16);
    p.max_range_m = 100.0;
    p.range_noise_std_m = 0.015;
    return p;
}

SensorParams os1_64() {
    SensorParams p;
    p.model = "os1_64";
    p.elevations_deg = evenlySpaced(-22.5, 22.5, 64);
    p.max_range_m = 120.0;
    p.range_noise_std_m = 0.015;
    return p;
}

SensorParams hdl32() {
    SensorParams p;
    p.model = "hdl32";
    p.elevations_deg = evenlySpaced(-30.67, 10.67, 32);
    p.max_range_m = 100.0;
    p.range_noise_std_m = 0.02;
    return p;
}

SensorParams os0_128() {
    SensorParams p;
    p.model = "os0_128";
    p.elevations_deg = evenlySpaced(-45.0, 45.0, 128);
    p.horizontal_resolution_deg = 360.0 / 1024.0;
    p.max_range_m = 50.0;
    p.range_noise_std_m = 0.015;
    return p;
}

SensorParams depthCamera() {
    SensorParams p;
    p.model = "depth_camera";
    p.type = SensorType::DepthCamera;
    p.min_range_m = 0.2;
    p.max_range_m = 6.0;
    p.range_noise_std_m = 0.005;
    return p;
}

SensorParams sensorPreset(const std::string& model) {
    if (model == "vlp16") return vlp16();
    if (model == "os1_64") return os1_64();
    if (model == "hdl32") return hdl32();
    if (model == "os0_128") return os0_128();
    if (model == "depth_camera") return depthCamera();
    throw std::invalid_argument("sensor model '" + model +
                                "' is unknown (vlp16, os1_64, hdl32, os0_128, depth_camera)");
}

void validate(const SensorParams& p) {
    auto require = [](bool ok, const char* field, const char* what) {
        if (!ok) throw std::invalid_argument(std::string(field) + ": " + what);
    };
    if (p.type == SensorType::SpinningLidar) {
        require(!p.elevations_deg.empty(), "elevations_deg", "needs at least one beam");
        require(p.horizontal_resolution_deg > 0.01 && p.horizontal_resolution_deg <= 45.0,
                "horizontal_resolution_deg", "must be in (0.01, 45] deg");
    } else {
        require(p.hfov_deg > 0 && p.hfov_deg < 170, "hfov_deg", "must be in (0, 170) deg");
        require(p.vfov_deg > 0 && p.vfov_deg < 170, "vfov_deg", "must be in (0, 170) deg");
        require(p.image_width >= 2 && p.image_width <= 4096, "image_width", "must be 2..4096 px");
        require(p.image_height >= 2 && p.image_height <= 4096, "image_height", "must be 2..4096 px");
    }
    require(p.min_range_m >= 0 && p.min_range_m < p.max_range_m, "min_range_m",
            "must be >= 0 and below max_range_m");
    require(p.range_noise_std_m >= 0 && p.range_noise_std_m < 1.0, "range_noise_std_m",
            "must be in [0, 1) m");
    require(p.dropout_probability >= 0 && p.dropout_probability <= 1, "dropout_probability",
            "must be in [0, 1]");
}

std::vector<Eigen::Vector3d> beamDirections(const SensorParams& p, double azimuth_offset_deg) {
    std::vector<Eigen::Vector3d> dirs;
    if (p.type == SensorType::SpinningLidar) {
        const int columns = static_cast<int>(std::round(360.0 / p.horizontal_resolution_deg));
        dirs.reserve(static_cast<std::size_t>(columns) * p.elevations_deg.size());
        for (int c = 0; c < columns; ++c) {
            const double az = (azimuth_offset_deg + c * p.horizontal_resolution_deg) * kDeg;
            for (double el_deg : p.elevations_deg) {
                const double el = el_deg * kDeg;
                dirs.emplace_back(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az),
                                  std::sin(el));
            }
        }
        return dirs;
    }
    // Pinhole: pixel (u, v) looks along (1, -tan_h * xn, -tan_v * yn), normalised.
    const double tan_h = std::tan(0.5 * p.hfov_deg * kDeg);
    const double tan_v = std::tan(0.5 * p.vfov_deg * kDeg);
    dirs.reserve(static_cast<std::size_t>(p.image_width) * p.image_height);
    for (int v = 0; v < p.image_height; ++v) {
        const double yn = 2.0 * (v + 0.5) / p.image_height - 1.0;
        for (int u = 0; u < p.image_width; ++u) {
            const double xn = 2.0 * (u + 0.5) / p.image_width - 1.0;
            dirs.push_back(Eigen::Vector3d(1.0, -tan_h * xn, -tan_v * yn).normalized());
        }
    }
    return dirs;
}

}  // namespace stairmap::sim
