#include "support/SyntheticScenes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/StairGenerators.h"

namespace stairmap::test {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kSlab = 0.1;  // [m] thickness of floors and stairwell walls

/// Stair frame in the robot frame: x along yaw, y to the left, origin `distance` ahead and
/// `lateral` to the side at height z.
Eigen::Isometry3d stairFrame(double distance, double lateral, double yaw, double z) {
    const Eigen::Vector2d h(std::cos(yaw), std::sin(yaw)), l(-std::sin(yaw), std::cos(yaw));
    const Eigen::Vector2d o = distance * h + lateral * l;
    return Eigen::Translation3d(o.x(), o.y(), z) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
}

}  // namespace

SceneBuilder::SceneBuilder(const SceneOptions& options) : opt_(options), rng_(options.seed) {}

void SceneBuilder::addFrameBox(const Eigen::Isometry3d& T_robot_frame, const Eigen::Vector3d& min,
                               const Eigen::Vector3d& max) {
    if ((max - min).minCoeff() <= 0.0) return;  // empty piece (e.g. a floor strip of no width)
    sim::Box box = sim::makeAxisAlignedBox(min, max);
    box.T_world_box = T_robot_frame * box.T_world_box;
    scene_.add(box);
    cloud_.reset();
}

StairTruth SceneBuilder::truthOf(std::size_t index, bool outward_reversed, double heading) const {
    const StaircaseTruth& st = scene_.truth().staircases.at(index);
    StairTruth t;
    for (const NosingSegment& n : st.nosings) t.nosings.push_back({n.start, n.end});
    if (outward_reversed) std::reverse(t.nosings.begin(), t.nosings.end());
    t.ascending = !outward_reversed;
    t.rise_m = st.rise_m;
    t.run_m = st.run_m;
    t.width_m = st.width_m;
    t.heading_rad = heading;
    t.location = 0.5 * (t.nosings.front().first + t.nosings.front().second);
    return t;
}

StairTruth SceneBuilder::addStairs(const StairSpec& s) {
    cloud_.reset();
    switch (s.kind) {
        case StairKind::Spiral: return addSpiral(s);
        case StairKind::Descending: return addDescending(s);
        case StairKind::Ascending:
        case StairKind::Hollow:
        case StairKind::Debris: return addStraight(s);
        case StairKind::Negative: break;
    }
    throw std::invalid_argument("SceneBuilder::addStairs: a staircase kind is needed");
}

StairTruth SceneBuilder::addStraight(const StairSpec& s) {
    const Eigen::Isometry3d T = stairFrame(s.distance_m, s.lateral_m, s.yaw_rad, opt_.floor_z);
    sim::StraightStairParams p;
    p.name = "stair_" + std::to_string(scene_.truth().staircases.size());
    p.kind = s.kind;
    p.origin = T.translation();
    p.heading_deg = s.yaw_rad / kDeg;
    p.num_risers = s.num_risers;
    p.rise_m = s.rise_m;
    p.run_m = s.run_m;
    p.width_m = s.width_m;
    p.open_risers = s.kind == StairKind::Hollow;
    p.landing_depth_m = 1.0;
    p.wall_left = p.wall_right = false;
    p.debris_count = s.kind == StairKind::Debris ? std::max(2, s.num_risers / 2) : 0;
    p.debris_seed = rng_();
    const std::size_t index = sim::addStraightStair(scene_, p);
    if (p.open_risers) {  // side stringers: inclined beams beside the floating treads
        const double dx = (s.num_risers - 0.5) * s.run_m, dz = s.num_risers * s.rise_m;
        const double pitch = std::atan2(dz, dx), len = std::hypot(dx, dz);
        for (double y : {s.width_m / 2 + 0.055, -s.width_m / 2 - 0.055}) {
            const Eigen::Isometry3d T_beam = T * Eigen::Translation3d(-0.5 * s.run_m, y, 0.0) *
                                             Eigen::AngleAxisd(-pitch, Eigen::Vector3d::UnitY());
            addFrameBox(T_beam, {0, -0.025, -0.05}, {len, 0.025, 0.0});
        }
    }
    return truthOf(index, false, s.yaw_rad);
}

StairTruth SceneBuilder::addSpiral(const StairSpec& s) {
    // Centre of rotation to the left of the first nosing; the flight turns counter-clockwise.
    const double R = 0.5 * s.run_m / std::sin(0.5 * s.turn_per_step_rad);
    sim::SpiralStairParams p;
    p.name = "spiral_" + std::to_string(scene_.truth().staircases.size());
    p.centre = stairFrame(s.distance_m, s.lateral_m + R, s.yaw_rad, opt_.floor_z).translation();
    p.num_risers = s.num_risers;
    p.rise_m = s.rise_m;
    p.column_radius_m = R - s.width_m / 2;
    p.outer_radius_m = R + s.width_m / 2;
    p.step_angle_deg = s.turn_per_step_rad / kDeg;
    p.start_angle_deg = s.yaw_rad / kDeg - 90.0;
    p.landing_angle_deg = 0.6 / kDeg;
    p.central_column = false;  // R is metres here: a wide well, not a column
    const std::size_t index = sim::addSpiralStair(scene_, p);
    return truthOf(index, false, s.yaw_rad + 0.5 * (s.num_risers - 1) * s.turn_per_step_rad);
}

StairTruth SceneBuilder::addDescending(const StairSpec& s) {
    if (stairwell_) throw std::logic_error("SceneBuilder: one descending flight per scene");
    const int n = s.num_risers;
    const double hw = s.width_m / 2, length = (n - 1) * s.run_m + 1.5, bottom = -n * s.rise_m;
    const Eigen::Isometry3d T_well = stairFrame(s.distance_m, s.lateral_m, s.yaw_rad, opt_.floor_z);
    // The simulator's flight ascends towards the robot: its top nosing is the floor's edge.
    sim::StraightStairParams p;
    p.name = "stair_" + std::to_string(scene_.truth().staircases.size());
    p.kind = StairKind::Descending;
    p.origin = T_well * Eigen::Vector3d((n - 1) * s.run_m, 0.0, bottom);
    p.heading_deg = s.yaw_rad / kDeg + 180.0;
    p.num_risers = n;
    p.rise_m = s.rise_m;
    p.run_m = s.run_m;
    p.width_m = s.width_m;
    p.landing_depth_m = 0.5;
    p.wall_left = p.wall_right = false;
    const std::size_t index = sim::addStraightStair(scene_, p);
    // The lower floor and the well's end wall. No side walls: they would hide the ends of the lower
    // nosings from an oblique view, and these scenes test geometry, not occlusion.
    addFrameBox(T_well, {(n - 1) * s.run_m, -hw, bottom - kSlab}, {length, hw, bottom});
    addFrameBox(T_well, {length, -hw, bottom}, {length + kSlab, hw, 0});
    stairwell_ = Stairwell{T_well, length + kSlab, hw};
    return truthOf(index, true, s.yaw_rad);
}

void SceneBuilder::addFloor() {
    const double H = opt_.floor_half_size_m;
    if (stairwell_) return addFloorAround(*stairwell_);
    addFrameBox(Eigen::Isometry3d::Identity(), {-H, -H, opt_.floor_z - kSlab}, {H, H, opt_.floor_z});
}

void SceneBuilder::addFloorAround(const Stairwell& w) {
    // Four slabs around the open rectangle [0, length] x [-half_width, half_width] of the well
    // frame, together covering a square of half size H around the robot.
    const Eigen::Vector3d r = w.T_robot_well.inverse() * Eigen::Vector3d::Zero();
    const double H = opt_.floor_half_size_m, s0 = r.x() - H, s1 = r.x() + H, t0 = r.y() - H,
                 t1 = r.y() + H;
    addFrameBox(w.T_robot_well, {s0, t0, -kSlab}, {0, t1, 0});
    addFrameBox(w.T_robot_well, {w.length, t0, -kSlab}, {s1, t1, 0});
    addFrameBox(w.T_robot_well, {0, w.half_width, -kSlab}, {w.length, t1, 0});
    addFrameBox(w.T_robot_well, {0, t0, -kSlab}, {w.length, -w.half_width, 0});
}

void SceneBuilder::addBox(const Eigen::Vector2d& c, double yaw, double len, double depth,
                          double z0, double height) {
    const Eigen::Isometry3d T =
        Eigen::Translation3d(c.x(), c.y(), 0) * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ());
    addFrameBox(T, {-len / 2, -depth / 2, z0}, {len / 2, depth / 2, z0 + height});
}

void SceneBuilder::addRamp(double distance, double yaw, double slope, double length, double width) {
    const Eigen::Isometry3d T = stairFrame(distance, 0, yaw, opt_.floor_z);
    const double top = length * std::tan(slope);
    addFrameBox(T * Eigen::AngleAxisd(-slope, Eigen::Vector3d::UnitY()),
                {0, -width / 2, -0.05}, {length / std::cos(slope), width / 2, 0});
    addFrameBox(T, {length, -width / 2, 0}, {length + 1.5, width / 2, top});  // platform
}

void SceneBuilder::addTable(const Eigen::Vector2d& c, double yaw, double len, double depth,
                            double height) {
    addBox(c, yaw, len, depth, opt_.floor_z + height - 0.03, 0.03);
    const Eigen::Vector2d u(std::cos(yaw), std::sin(yaw)), v(-std::sin(yaw), std::cos(yaw));
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
            const Eigen::Vector2d leg = c + sx * (len / 2 - 0.05) * u + sy * (depth / 2 - 0.05) * v;
            addBox(leg, yaw, 0.05, 0.05, opt_.floor_z, height - 0.03);
        }
}

void SceneBuilder::addTiers(double distance, double yaw, int tiers, double rise, double run,
                            double width, double top_depth) {
    const Eigen::Isometry3d T = stairFrame(distance, 0, yaw, opt_.floor_z);
    for (int k = 1; k <= tiers; ++k) {
        const double x = (k - 1) * run, depth = k == tiers ? top_depth : run;
        addFrameBox(T, {x, -width / 2, 0}, {x + depth, width / 2, k * rise});
    }
}

void SceneBuilder::addWall(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double height) {
    const Eigen::Vector2d d = b - a;
    const Eigen::Isometry3d T = Eigen::Translation3d(a.x(), a.y(), opt_.floor_z) *
                                Eigen::AngleAxisd(std::atan2(d.y(), d.x()), Eigen::Vector3d::UnitZ());
    addFrameBox(T, {0, -0.025, 0}, {d.norm(), 0.025, height});
}

const PointCloud& SceneBuilder::cloud() const {
    if (cloud_) return *cloud_;
    cloud_.emplace();
    const Eigen::Vector3d view(0, 0, opt_.floor_z + opt_.view_height_m);
    const double step = opt_.spacing_m / 3.0;  // [rad] spacing_m at 3 m
    const int n_az = static_cast<int>(std::ceil(2 * M_PI / step));
    const double el_min = -88 * kDeg, el_max = 30 * kDeg;
    const int n_el = static_cast<int>(std::ceil((el_max - el_min) / step));
    std::normal_distribution<double> noise(0.0, opt_.noise_m);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < n_el; ++i) {
        const double el = el_min + (i + 0.5) * step, ce = std::cos(el), se = std::sin(el);
        for (int j = 0; j < n_az; ++j) {
            const double az = (j + unit(rng_)) * 2 * M_PI / n_az;  // jittered: no aliasing
            const sim::Ray ray{view, {ce * std::cos(az), ce * std::sin(az), se}};
            const std::optional<double> d = scene_.castRay(ray, opt_.max_range_m);
            if (!d) continue;
            const Eigen::Vector3d p = view + *d * ray.direction;
            const double r = p.head<2>().norm();
            if (opt_.sparse_from_m > 0 && r > opt_.sparse_from_m) {
                const double q = opt_.sparse_from_m / r;
                if (unit(rng_) > q * q) continue;
            }
            cloud_->push_back((p + Eigen::Vector3d(noise(rng_), noise(rng_), noise(rng_))).cast<float>());
        }
    }
    return *cloud_;
}

}  // namespace stairmap::test
