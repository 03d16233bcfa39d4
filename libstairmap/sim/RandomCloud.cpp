#include "sim/RandomCloud.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "sim/RandomDraw.h"
#include "sim/RandomSceneBuild.h"
#include "sim/ScanSimulator.h"
#include "sim/SceneFurniture.h"

namespace stairmap::sim {

namespace {
using V3 = Eigen::Vector3d;
constexpr double kDeg = M_PI / 180.0;
constexpr double kMapHalfM = 4.0;  // [m] elevation map square around the robot

Eigen::Isometry3d robotFrame(const SensorSpec& s) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = V3(0, 0, s.base_height_m);
    return T;
}

PointCloud elevationMap(const Scene& scene, const RandomSceneSpec& spec, RandomDraw& noise) {
    const double cell = spec.sensor.cell_m;
    const int n = static_cast<int>(std::floor(2.0 * kMapHalfM / cell));
    const double top = 8.0;  // rays start above everything a scene holds
    PointCloud cloud;
    Ray ray;
    ray.direction = -V3::UnitZ();
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double x = -kMapHalfM + (i + 0.5) * cell, y = -kMapHalfM + (j + 0.5) * cell;
            ray.origin = V3(x, y, top);
            const auto t = scene.castRay(ray, 2.0 * top);
            if (!t) continue;
            const double z = top - *t + 0.003 * noise.gauss() - spec.sensor.base_height_m;
            cloud.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
        }
    }
    return cloud;
}

/// Scans along the last path_length_m before the pose (the robot walked forward along x), each
/// with a random body roll/pitch and a small heading wobble, mapped with their true poses.
PointCloud scansAlongPath(const Scene& scene, const RandomSceneSpec& spec, RandomDraw& noise) {
    const SensorSpec& s = spec.sensor;
    const SensorParams params = randomSensorParams(s);
    const Eigen::Isometry3d T_robot_sensor = randomSensorMount(s);
    const Eigen::Isometry3d T_world_robot = robotFrame(s);
    std::mt19937 rng(spec.noise_seed);
    PointCloud cloud;
    for (int k = 0; k < s.scans; ++k) {
        const double back = s.scans > 1 ? s.path_length_m * (s.scans - 1 - k) / (s.scans - 1) : 0.0;
        Eigen::Isometry3d T_robot_robotk = Eigen::Isometry3d::Identity();
        T_robot_robotk.translation() = V3(-back, 0.0, 0.0);
        T_robot_robotk.linear() =
            (Eigen::AngleAxisd((k + 1 < s.scans ? 1.0 : 0.0) * noise.gauss() * kDeg, V3::UnitZ()) *
             Eigen::AngleAxisd(s.tilt_std_deg * noise.gauss() * kDeg, V3::UnitY()) *
             Eigen::AngleAxisd(s.tilt_std_deg * noise.gauss() * kDeg, V3::UnitX()))
                .toRotationMatrix();
        const Eigen::Isometry3d T_robot_sensork = T_robot_robotk * T_robot_sensor;
        const double azimuth = noise.uniform(0.0, params.horizontal_resolution_deg);
        const auto scan = simulateScan(scene, T_world_robot * T_robot_sensork, params, rng, azimuth);
        const Eigen::Isometry3f T = T_robot_sensork.cast<float>();
        for (const auto& p : scan) cloud.push_back(T * p);
    }
    return cloud;
}

/// Up-flight unit vector across nosing i (towards the next nosing, away from the previous one).
Eigen::Vector2d upFlight(const StaircaseTruth& s, std::size_t i) {
    const auto& n = s.nosings[i];
    const Eigen::Vector2d t = (n.end - n.start).head<2>().normalized();
    Eigen::Vector2d u(-t.y(), t.x());
    const bool has_next = i + 1 < s.nosings.size();
    const Eigen::Vector2d to = has_next ? (s.nosings[i + 1].centre() - n.centre()).head<2>()
                                        : (n.centre() - s.nosings[i - 1].centre()).head<2>();
    return u.dot(to) < 0 ? Eigen::Vector2d(-u) : u;
}

int seenOf(const StaircaseTruth& s, const PointCloud& cloud) {
    if (s.nosings.size() < 2) return 0;
    int seen = 0;
    const double depth = std::clamp(s.run_m, 0.15, 0.40) - 0.02;
    for (std::size_t i = 0; i < s.nosings.size(); ++i) {
        const auto& n = s.nosings[i];
        const Eigen::Vector2d a = n.start.head<2>();
        const Eigen::Vector2d t = (n.end - n.start).head<2>();
        const double len = t.norm();
        const Eigen::Vector2d th = t / len, u = upFlight(s, i);
        const double z = n.centre().z();
        int count = 0;
        for (const auto& p : cloud) {
            if (p.z() < z - s.rise_m + 0.02 || p.z() > z + 0.04) continue;
            const Eigen::Vector2d q = p.head<2>().cast<double>() - a;
            const double along = th.dot(q), across = u.dot(q);
            if (along < 0.0 || along > len || across < -0.03 || across > depth) continue;
            if (++count >= kSeenPoints) break;
        }
        if (count >= kSeenPoints) ++seen;
    }
    return seen;
}
}  // namespace

SensorParams randomSensorParams(const SensorSpec& s) {
    if (s.kind == RandomSensorKind::ElevationMap) return SensorParams{};
    SensorParams p = sensorPreset(s.model);
    if (s.model == "hdl32") p.horizontal_resolution_deg = 0.25;
    if (s.model == "os1_64") p.horizontal_resolution_deg = 360.0 / 1024.0;
    if (s.model == "os0_128") p.horizontal_resolution_deg = 360.0 / 512.0;
    if (p.type == SensorType::SpinningLidar) p.max_range_m = 25.0;
    p.dropout_probability = 0.02;
    return p;
}

Eigen::Isometry3d randomSensorMount(const SensorSpec& s) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = V3(0, 0, s.mount_height_m);
    T.linear() = Eigen::AngleAxisd(s.pitch_deg * kDeg, V3::UnitY()).toRotationMatrix();
    return T;
}

PointCloud observeRandomScene(const Scene& scene, const RandomSceneSpec& spec) {
    RandomDraw noise(spec.seed, static_cast<std::uint64_t>(spec.index), spec.noise_seed);
    if (spec.sensor.kind == RandomSensorKind::ElevationMap) return elevationMap(scene, spec, noise);
    return scansAlongPath(scene, spec, noise);
}

std::vector<int> seenNosings(const SceneTruth& truth, const PointCloud& cloud) {
    std::vector<int> seen;
    for (const auto& s : truth.staircases) seen.push_back(seenOf(s, cloud));
    return seen;
}

RandomCloud makeRandomCloud(std::uint64_t seed, int index, const RandomRanges& ranges, int max_attempts) {
    RandomCloud out;
    for (int attempt = 0; attempt < max_attempts; ++attempt) {
        out.spec = drawRandomScene(seed, index, attempt, ranges);
        const Scene scene = buildRandomScene(out.spec);
        out.cloud = observeRandomScene(scene, out.spec);
        out.attempts = attempt + 1;
        out.T_robot_sensor = randomSensorMount(out.spec.sensor);
        SceneTruth world = scene.truth();
        world.observer_floor_z = 0.0;
        out.truth = transformTruth(world, robotFrame(out.spec.sensor).inverse(), "robot");
        out.seen_nosings = seenNosings(out.truth, out.cloud);
        bool redraw = false;
        for (std::size_t i = 0; i < out.truth.staircases.size(); ++i) {
            const int seen = out.seen_nosings[i];
            auto& stair = out.truth.staircases[i];
            stair.seen_as.reset();
            if (seen >= kExpectedNosings) {
                stair.seen_as = out.spec.flights[i].descending ? StairDirection::Descending
                                                               : StairDirection::Ascending;
            }
            redraw = redraw || (seen > 1 && seen < kExpectedNosings) || (i == 0 && seen <= 1);
        }
        if (!redraw) break;
    }
    return out;
}

}  // namespace stairmap::sim
