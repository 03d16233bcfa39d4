#include <cmath>
#include <sstream>

#include "io/config/SceneIniParts.h"

namespace stairmap::io::detail {

namespace {
constexpr double kDeg = M_PI / 180.0;

Eigen::Isometry3d mountPose(const IniFieldReader& ini, const std::string& s) {
    // Roll about x, pitch about y, yaw about z: R = Rz(yaw) Ry(pitch) Rx(roll). Positive pitch
    // tilts the sensor's x axis downwards (legged robots look at the ground ahead).
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = (Eigen::AngleAxisd(ini.getDouble(s, "mount_yaw_deg", 0.0) * kDeg, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(ini.getDouble(s, "mount_pitch_deg", 0.0) * kDeg, Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(ini.getDouble(s, "mount_roll_deg", 0.0) * kDeg, Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
    // Read before assigning: a getDouble that throws inside Eigen's comma initializer unwinds
    // through its destructor, which asserts that every coefficient was set (abort in debug).
    const double x = ini.getDouble(s, "mount_x_m", 0.0);
    const double y = ini.getDouble(s, "mount_y_m", 0.0);
    const double z = ini.getDouble(s, "mount_z_m", 0.4);
    T.translation() = Eigen::Vector3d(x, y, z);
    return T;
}

std::vector<Eigen::Vector3d> waypoints(const IniFieldReader& ini, const std::string& section) {
    std::vector<Eigen::Vector3d> points;
    for (const auto& g : ini.getGroups(section, "waypoints", 3)) points.emplace_back(g[0], g[1], g[2]);
    if (points.size() < 2) ini.fail(section, "waypoints", "needs at least two 'x y floor_z' groups");
    return points;
}

/// `odom_frame = x y z yaw_deg`: the robot's own frame in the world (default: the world). A real
/// robot reports poses in its own odometry frame; a fleet must find these transforms.
Eigen::Isometry3d odomFrame(const IniFieldReader& ini, const std::string& section) {
    if (!ini.has(section, "odom_frame")) return Eigen::Isometry3d::Identity();
    const std::vector<double> v = ini.getNumbers(section, "odom_frame");
    if (v.size() != 4) ini.fail(section, "odom_frame", "expected 'x y z yaw_deg'");
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
    T.linear() = Eigen::AngleAxisd(v[3] * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return T;
}

/// Reads one sensor section ([sensor] or a robot's own, named by its `sensor` key).
sim::MountedSensor loadMountedSensor(const IniFieldReader& ini, const std::string& s) {
    sim::MountedSensor mounted;
    const std::string model = ini.getString(s, "model", "vlp16");
    checked(ini, s, [&] { mounted.sensor = sim::sensorPreset(model); });
    auto& p = mounted.sensor;
    p.horizontal_resolution_deg = ini.getDouble(s, "horizontal_resolution_deg", p.horizontal_resolution_deg);
    p.min_range_m = ini.getDouble(s, "min_range_m", p.min_range_m);
    p.max_range_m = ini.getDouble(s, "max_range_m", p.max_range_m);
    p.range_noise_std_m = ini.getDouble(s, "range_noise_std_m", p.range_noise_std_m);
    p.dropout_probability = ini.getDouble(s, "dropout_probability", p.dropout_probability);
    p.hfov_deg = ini.getDouble(s, "hfov_deg", p.hfov_deg);
    p.vfov_deg = ini.getDouble(s, "vfov_deg", p.vfov_deg);
    p.image_width = ini.getInt(s, "image_width", p.image_width);
    p.image_height = ini.getInt(s, "image_height", p.image_height);
    if (ini.has(s, "elevations_deg")) p.elevations_deg = ini.getNumbers(s, "elevations_deg");
    checked(ini, s, [&] { sim::validate(p); });
    mounted.label = ini.getString(s, "label", "lidar");
    mounted.T_robot_sensor = mountPose(ini, s);
    return mounted;
}
}  // namespace

void loadSensorSection(const IniFieldReader& ini, sim::SimulationConfig& config) {
    const sim::MountedSensor mounted = loadMountedSensor(ini, "sensor");
    config.sensor = mounted.sensor;
    config.sensor_label = mounted.label;
    config.T_robot_sensor = mounted.T_robot_sensor;
    config.base_height_m = ini.getDouble("robot", "base_height_m", config.base_height_m);
    if (config.base_height_m < 0 || config.base_height_m > 5)
        ini.fail("robot", "base_height_m", "must be in [0, 5] m");
}

void loadRobotRuns(const IniFieldReader& ini, sim::SimulationConfig& config) {
    std::vector<std::string> sections;
    if (ini.has("trajectory", "robots")) {
        std::istringstream names(ini.getString("trajectory", "robots", ""));
        for (std::string n; names >> n;) sections.push_back(n);
    } else if (ini.has("trajectory", "waypoints")) {
        sections.push_back("trajectory");
    }
    config.rawlog_quantum_m = ini.getDouble("trajectory", "quantum_m", config.rawlog_quantum_m);
    if (!(config.rawlog_quantum_m > 0 && config.rawlog_quantum_m <= 0.05))
        ini.fail("trajectory", "quantum_m", "must be in (0, 0.05] m");
    config.rawlog_sort_points = ini.getBool("trajectory", "sort_points", config.rawlog_sort_points);
    for (const auto& section : sections) {
        sim::RobotRun run;
        run.name = section == "trajectory" ? config.name : section;
        auto& t = run.trajectory;
        t.waypoints = waypoints(ini, section);
        t.speed_mps = ini.getDouble(section, "speed_mps", t.speed_mps);
        t.yaw_rate_dps = ini.getDouble(section, "yaw_rate_dps", t.yaw_rate_dps);
        t.scan_rate_hz = ini.getDouble(section, "scan_rate_hz", t.scan_rate_hz);
        t.start_time_s = ini.getDouble(section, "start_time_s", t.start_time_s);
        t.base_height_m = ini.getDouble(section, "base_height_m", config.base_height_m);
        if (t.base_height_m < 0 || t.base_height_m > 5)
            ini.fail(section, "base_height_m", "must be in [0, 5] m");
        run.mounted = {config.sensor, config.sensor_label, config.T_robot_sensor};
        if (ini.has(section, "sensor")) {
            const std::string sensor_section = ini.getString(section, "sensor", "");
            if (sensor_section.empty()) ini.fail(section, "sensor", "must name a sensor section");
            run.mounted = loadMountedSensor(ini, sensor_section);
        }
        run.drift.xy_std_per_m = ini.getDouble(section, "drift_xy_std_per_m", 0.0);
        run.drift.z_std_per_m = ini.getDouble(section, "drift_z_std_per_m", 0.0);
        run.drift.yaw_std_deg_per_m = ini.getDouble(section, "drift_yaw_std_deg_per_m", 0.0);
        run.drift.seed = static_cast<unsigned>(ini.getInt(section, "drift_seed", 1));
        run.sway.tilt_std_deg = ini.getDouble(section, "sway_tilt_deg", 0.0);
        run.sway.seed = static_cast<unsigned>(ini.getInt(section, "sway_seed", 1));
        run.T_world_odom = odomFrame(ini, section);
        if (!(run.sway.tilt_std_deg >= 0 && run.sway.tilt_std_deg <= 10))
            ini.fail(section, "sway_tilt_deg", "must be in [0, 10] deg");
        if (run.drift.xy_std_per_m < 0 || run.drift.z_std_per_m < 0 || run.drift.yaw_std_deg_per_m < 0)
            ini.fail(section, "drift_*", "drift standard deviations must be >= 0");
        checked(ini, section, [&] { sim::validate(t); });
        config.robots.push_back(run);
    }
}

void loadCloudSection(const IniFieldReader& ini, sim::SimulationConfig& config) {
    const std::string s = "clouds";
    for (const auto& g : ini.getGroups(s, "poses", 4)) {
        config.cloud_poses.push_back({Eigen::Vector3d(g[0], g[1], g[2]), g[3]});
    }
    auto& c = config.cloud_params;
    c.scans_per_cloud = ini.getInt(s, "scans_per_cloud", c.scans_per_cloud);
    c.jitter_xy_m = ini.getDouble(s, "jitter_xy_m", c.jitter_xy_m);
    c.jitter_yaw_deg = ini.getDouble(s, "jitter_yaw_deg", c.jitter_yaw_deg);
    c.jitter_tilt_deg = ini.getDouble(s, "jitter_tilt_deg", c.jitter_tilt_deg);
    c.quantum_m = ini.getDouble(s, "quantum_m", c.quantum_m);
    c.sort_points = ini.getBool(s, "sort_points", c.sort_points);
    checked(ini, s, [&] { sim::validate(c); });
    config.cloud_extension = ini.getString(s, "format", "pcd");
    const std::string& e = config.cloud_extension;
    const std::string plain = e.size() > 3 && e.compare(e.size() - 3, 3, ".gz") == 0 ? e.substr(0, e.size() - 3) : e;
    if (plain != "pcd" && plain != "ply" && plain != "xyz")
        ini.fail(s, "format", "must be pcd, ply or xyz, optionally gzipped (pcd.gz, ply.gz, xyz.gz)");
    config.cloud_first_index = ini.getInt(s, "first_index", 0);
}

}  // namespace stairmap::io::detail
