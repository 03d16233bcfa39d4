#pragma once
// Sensor models: spinning multi-beam LiDARs and a depth camera, as a fixed set of beam directions
// in the sensor frame (x forward, y left, z up) plus range limits and noise.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace stairmap::sim {

enum class SensorType { SpinningLidar, DepthCamera };

struct SensorParams {
    std::string model = "vlp16";        ///< preset name: vlp16 | os1_64 | hdl32 | os0_128 | depth_camera
    SensorType type = SensorType::SpinningLidar;
    // --- spinning LiDAR
    std::vector<double> elevations_deg;  ///< [deg] one entry per beam (laser ring)
    double horizontal_resolution_deg = 0.2;  ///< [deg] azimuth step of one revolution
    // --- depth camera (pinhole, looking along +x)
    double hfov_deg = 87.0;              ///< [deg] horizontal field of view
    double vfov_deg = 58.0;              ///< [deg] vertical field of view
    int image_width = 160;               ///< [px]
    int image_height = 100;              ///< [px]
    // --- common
    double min_range_m = 0.3;            ///< [m] closer returns are dropped
    double max_range_m = 100.0;          ///< [m] farther surfaces give no return
    double range_noise_std_m = 0.01;     ///< [m] Gaussian noise on range (depth camera: at 1 m,
                                         ///< growing with range squared)
    double dropout_probability = 0.0;    ///< [0..1] chance a valid return is lost
};

/// Presets. Throws std::invalid_argument for an unknown name.
SensorParams sensorPreset(const std::string& model);
SensorParams vlp16();   ///< 16 beams, -15..+15 deg every 2 deg, 100 m
SensorParams os1_64();  ///< 64 beams evenly over -22.5..+22.5 deg, 120 m
SensorParams hdl32();   ///< 32 beams, -30.67..+10.67 deg every 1.333 deg, 100 m
SensorParams os0_128();  ///< 128 beams evenly over -45..+45 deg, 1024 columns, 50 m
SensorParams depthCamera();  ///< RealSense-like 87x58 deg, 0.2..6 m

/// Throws std::invalid_argument naming the field if a parameter is out of range.
void validate(const SensorParams& params);

/// Unit beam directions in the sensor frame for one scan; azimuth_offset_deg shifts a spinning
/// LiDAR's start angle (successive revolutions rarely align). Order: azimuth-major.
std::vector<Eigen::Vector3d> beamDirections(const SensorParams& params,
                                            double azimuth_offset_deg = 0.0);

}  // namespace stairmap::sim
