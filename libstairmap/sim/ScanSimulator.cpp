#include "sim/ScanSimulator.h"

namespace stairmap::sim {

PointCloud simulateScan(const Scene& scene, const Eigen::Isometry3d& T_world_sensor,
                        const SensorParams& params, std::mt19937& rng, double azimuth_offset_deg) {
    const auto directions = beamDirections(params, azimuth_offset_deg);
    std::normal_distribution<double> noise(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const bool is_camera = params.type == SensorType::DepthCamera;

    PointCloud points;
    points.reserve(directions.size());
    Ray ray;
    ray.origin = T_world_sensor.translation();
    for (const auto& dir_sensor : directions) {
        ray.direction = T_world_sensor.linear() * dir_sensor;
        const auto t = scene.castRay(ray, params.max_range_m);
        // Draw both random numbers for every beam so one beam's outcome does not shift the others.
        const double n = noise(rng);
        const double u = uniform(rng);
        if (!t || *t < params.min_range_m) continue;
        if (u < params.dropout_probability) continue;
        // Depth cameras: noise grows with depth^2 (structured-light/stereo triangulation).
        const double sigma = is_camera ? params.range_noise_std_m * (*t) * (*t)
                                       : params.range_noise_std_m;
        const double range = *t + sigma * n;
        if (range <= 0.0) continue;
        points.push_back((range * dir_sensor).cast<float>());
    }
    return points;
}

}  // namespace stairmap::sim
