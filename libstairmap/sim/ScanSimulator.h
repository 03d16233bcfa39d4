#pragma once
// Casts one scan of a sensor model into a scene.

#include <Eigen/Geometry>
#include <random>

#include "core/PointCloud.h"
#include "sim/Scene.h"
#include "sim/SensorModel.h"

namespace stairmap::sim {

/// Simulates one scan. Returns the hit points in the SENSOR frame [m]. Range noise (Gaussian along
/// the beam) and dropouts are drawn from `rng`, so a seeded generator makes the scan reproducible.
/// Cost: beams x primitives slab tests (VLP-16 at 0.2 deg over ~100 primitives: a few ms).
PointCloud simulateScan(const Scene& scene, const Eigen::Isometry3d& T_world_sensor,
                        const SensorParams& params, std::mt19937& rng,
                        double azimuth_offset_deg = 0.0);

}  // namespace stairmap::sim
