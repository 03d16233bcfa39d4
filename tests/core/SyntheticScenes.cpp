#include "SyntheticScenes.h"

#include <cmath>

namespace stairmap::test {
namespace {

/// Local stair frame: x along the heading, y to the left, z absolute.
struct Frame {
    Eigen::Vector2d origin, h, l;
    Frame(double distance, double lateral, double yaw)
        : h(std::cos(yaw), std::sin(yaw)), l(-std::sin(yaw), std::cos(yaw)) {
        origin = distance * h + lateral * l;
    }
    Eigen::Vector3d point(double x, double y, double z) const {
        const Eigen::Vector2d p = origin + x * h + y * l;
        return {p.x(), p.y(), z};
    }
    Eigen::Vector3d vec(double x, double y, double z) const {
        const Eigen::Vector2d p = x * h + y * l;
        return {p.x(), p.y(), z};
    }
};

}  // namespace

std::string toString(StairKind kind) {
    switch (kind) {
        case StairKind::Ascending: return "ascending";
        case StairKind::Hollow: return "hollow";
        case StairKind::Spiral: return "spiral";
        case StairKind::Descending: return "descending";
        case StairKind::Debris: return "debris";
    }
    return "?";
}

SceneBuilder::SceneBuilder(const SceneOptions& options) : opt_(options), rng_(options.seed) {}

void SceneBuilder::addPoint(const Eigen::Vector3d& p) {
    std::normal_distribution<double> noise(0.0, opt_.noise_m);
    const double r = p.head<2>().norm();
    if (opt_.sparse_from_m > 0 && r > opt_.sparse_from_m) {
        std::uniform_real_distribution<double> keep(0.0, 1.0);
        const double q = opt_.sparse_from_m / r;
        if (keep(rng_) > q * q) return;
    }
    const Eigen::Vector3d n(noise(rng_), noise(rng_), noise(rng_));
    cloud_.push_back((p + n).cast<float>());
}

void SceneBuilder::sampleQuad(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                              const Eigen::Vector3d& v, double spacing) {
    const int nu = std::max(1, static_cast<int>(std::ceil(u.norm() / spacing)));
    const int nv = std::max(1, static_cast<int>(std::ceil(v.norm() / spacing)));
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    for (int i = 0; i < nu; ++i) {
        for (int j = 0; j < nv; ++j) {
            const double s = (i + jitter(rng_)) / nu, t = (j + jitter(rng_)) / nv;
            addPoint(origin + s * u + t * v);
        }
    }
}

bool SceneBuilder::inHole(const Eigen::Vector2d& p) const {
    for (const Hole& h : holes_) {
        const Eigen::Vector2d d = p - h.origin;
        const double s = d.dot(h.axis_u), t = d.dot(h.axis_v);
        if (s >= 0 && s <= h.len_u && std::abs(t) <= h.half_v) return true;
    }
    return false;
}

void SceneBuilder::addFloor() {
    const double H = opt_.floor_half_size_m, sp = opt_.floor_spacing_m;
    const int n = static_cast<int>(2 * H / sp);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const Eigen::Vector2d p(-H + (i + jitter(rng_)) * sp, -H + (j + jitter(rng_)) * sp);
            if (!inHole(p)) addPoint({p.x(), p.y(), opt_.floor_z});
        }
    }
}

StairTruth SceneBuilder::addStairs(const StairSpec& s) {
    switch (s.kind) {
        case StairKind::Ascending: return addStraight(s, false);
        case StairKind::Hollow: return addStraight(s, true);
        case StairKind::Spiral: return addSpiral(s);
        case StairKind::Descending: return addDescending(s);
        case StairKind::Debris: {
            StairTruth t = addStraight(s, false);
            const Frame f(s.distance_m, s.lateral_m, s.yaw_rad);
            std::uniform_real_distribution<double> u(-0.3, 0.3);
            for (int k = 2; k < s.num_risers; k += 2) {  // a small box on every other tread
                const Eigen::Vector3d c = f.point((k - 1) * s.run_m + 0.12, u(rng_) * s.width_m, 0);
                addBox(c.head<2>(), s.yaw_rad + u(rng_), 0.18, 0.12, opt_.floor_z + k * s.rise_m,
                       0.06 + 0.1 * std::abs(u(rng_)));
            }
            return t;
        }
    }
    return {};
}

StairTruth SceneBuilder::addStraight(const StairSpec& s, bool hollow) {
    const Frame f(s.distance_m, s.lateral_m, s.yaw_rad);
    const double w = s.width_m, z0 = opt_.floor_z, sp = opt_.spacing_m;
    const double thick = 0.04;  // hollow treads: thin slabs with a front face
    StairTruth t;
    for (int k = 1; k <= s.num_risers; ++k) {
        const double x = (k - 1) * s.run_m, z = z0 + k * s.rise_m;
        const bool landing = k == s.num_risers;
        const double depth = landing ? 1.0 : (hollow ? 0.9 * s.run_m : s.run_m);
        sampleQuad(f.point(x, -w / 2, z), f.vec(depth, 0, 0), f.vec(0, w, 0), sp);
        if (hollow)
            sampleQuad(f.point(x, -w / 2, z - thick), f.vec(0, 0, thick), f.vec(0, w, 0), sp);
        else
            sampleQuad(f.point(x, -w / 2, z - s.rise_m), f.vec(0, 0, s.rise_m), f.vec(0, w, 0), sp);
        t.nosings.push_back({f.point(x, w / 2, z), f.point(x, -w / 2, z)});
    }
    if (hollow) {  // side stringers: inclined strips
        const double len_x = (s.num_risers - 1) * s.run_m, len_z = s.num_risers * s.rise_m;
        for (double y : {w / 2 + 0.03, -w / 2 - 0.08})
            sampleQuad(f.point(-s.run_m * 0.5, y, z0), f.vec(len_x + 0.5 * s.run_m, 0, len_z),
                       f.vec(0, 0.05, 0), sp);
    }
    t.ascending = true;
    t.rise_m = s.rise_m;
    t.run_m = s.run_m;
    t.width_m = w;
    t.heading_rad = s.yaw_rad;
    t.location = 0.5 * (t.nosings[0].first + t.nosings[0].second);
    return t;
}

StairTruth SceneBuilder::addSpiral(const StairSpec& s) {
    const Frame f(s.distance_m, s.lateral_m, s.yaw_rad);
    const double w = s.width_m, R = 0.5 * s.run_m / std::sin(0.5 * s.turn_per_step_rad);
    const double r_in = R - w / 2, r_out = R + w / 2, z0 = opt_.floor_z, sp = opt_.spacing_m;
    // Centre of rotation to the left of the first nosing; steps turn counter-clockwise about it.
    auto at = [&](double r, double phi, double z) {  // phi = 0 on the first nosing
        return f.point(r * std::sin(phi), R - r * std::cos(phi), z);
    };
    StairTruth t;
    for (int k = 1; k <= s.num_risers; ++k) {
        const double phi0 = (k - 1) * s.turn_per_step_rad, z = z0 + k * s.rise_m;
        const double phi1 = k == s.num_risers ? phi0 + 0.6 : phi0 + s.turn_per_step_rad;
        for (double r = r_in + 0.5 * sp; r < r_out; r += sp) {  // wedge tread, polar sampling
            const int n = std::max(1, static_cast<int>((phi1 - phi0) * r / sp));
            for (int i = 0; i < n; ++i) addPoint(at(r, phi0 + (i + 0.5) * (phi1 - phi0) / n, z));
        }
        sampleQuad(at(r_in, phi0, z - s.rise_m), at(r_out, phi0, z - s.rise_m) - at(r_in, phi0, z - s.rise_m),
                   Eigen::Vector3d(0, 0, s.rise_m), sp);
        t.nosings.push_back({at(r_in, phi0, z), at(r_out, phi0, z)});
    }
    t.ascending = true;
    t.rise_m = s.rise_m;
    t.run_m = 2 * R * std::sin(0.5 * s.turn_per_step_rad);
    t.width_m = w;
    t.heading_rad = s.yaw_rad + 0.5 * (s.num_risers - 1) * s.turn_per_step_rad;
    t.location = 0.5 * (t.nosings[0].first + t.nosings[0].second);
    return t;
}

StairTruth SceneBuilder::addDescending(const StairSpec& s) {
    const Frame f(s.distance_m, s.lateral_m, s.yaw_rad);
    const double w = s.width_m, z0 = opt_.floor_z, sp = opt_.spacing_m;
    const double L = (s.num_risers - 1) * s.run_m + 1.5;
    holes_.push_back({f.origin, f.h, f.l, L, w / 2});
    StairTruth t;
    for (int k = 0; k < s.num_risers; ++k) {
        t.nosings.push_back({f.point(k * s.run_m, w / 2, z0 - k * s.rise_m),
                             f.point(k * s.run_m, -w / 2, z0 - k * s.rise_m)});
        const double x = k * s.run_m, ztop = z0 - k * s.rise_m;
        sampleQuad(f.point(x, -w / 2, ztop - s.rise_m), f.vec(0, 0, s.rise_m), f.vec(0, w, 0), sp);
        const double depth = k == s.num_risers - 1 ? L - x : s.run_m;  // last: bottom floor
        sampleQuad(f.point(x, -w / 2, ztop - s.rise_m), f.vec(depth, 0, 0), f.vec(0, w, 0), sp);
    }
    const double zb = z0 - s.num_risers * s.rise_m, hgt = z0 - zb;
    for (double y : {-w / 2, w / 2})  // stairwell side walls
        sampleQuad(f.point(0, y, zb), f.vec(L, 0, 0), f.vec(0, 0, hgt), sp);
    sampleQuad(f.point(L, -w / 2, zb), f.vec(0, w, 0), f.vec(0, 0, hgt), sp);
    t.ascending = false;
    t.rise_m = s.rise_m;
    t.run_m = s.run_m;
    t.width_m = w;
    t.heading_rad = s.yaw_rad;
    t.location = 0.5 * (t.nosings[0].first + t.nosings[0].second);
    return t;
}

void SceneBuilder::addBox(const Eigen::Vector2d& c, double yaw, double len, double depth,
                          double z0, double height) {
    const Frame f(0, 0, yaw);
    const Eigen::Vector3d o = Eigen::Vector3d(c.x(), c.y(), z0) + f.vec(-len / 2, -depth / 2, 0);
    const Eigen::Vector3d u = f.vec(len, 0, 0), v = f.vec(0, depth, 0), up(0, 0, height);
    const double sp = opt_.spacing_m;
    sampleQuad(o + up, u, v, sp);
    sampleQuad(o, u, up, sp);
    sampleQuad(o + v, u, up, sp);
    sampleQuad(o, v, up, sp);
    sampleQuad(o + u, v, up, sp);
}

void SceneBuilder::addRamp(double distance, double yaw, double slope, double length, double width) {
    const Frame f(distance, 0, yaw);
    const double z0 = opt_.floor_z, top = length * std::tan(slope), sp = opt_.spacing_m;
    sampleQuad(f.point(0, -width / 2, z0), f.vec(length, 0, top), f.vec(0, width, 0), sp);
    sampleQuad(f.point(length, -width / 2, z0 + top), f.vec(1.5, 0, 0), f.vec(0, width, 0), sp);
    sampleQuad(f.point(length + 1.5, -width / 2, z0), f.vec(0, width, 0), f.vec(0, 0, top), sp);
}

void SceneBuilder::addTable(const Eigen::Vector2d& c, double yaw, double len, double depth,
                            double height) {
    addBox(c, yaw, len, depth, opt_.floor_z + height - 0.03, 0.03);
    const Frame f(0, 0, yaw);
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) {
            const Eigen::Vector3d leg = f.vec(sx * (len / 2 - 0.05), sy * (depth / 2 - 0.05), 0);
            addBox(c + leg.head<2>(), yaw, 0.05, 0.05, opt_.floor_z, height - 0.03);
        }
}

void SceneBuilder::addTiers(double distance, double yaw, int tiers, double rise, double run,
                            double width, double top_depth) {
    const Frame f(distance, 0, yaw);
    const double sp = opt_.spacing_m, z0 = opt_.floor_z;
    for (int k = 1; k <= tiers; ++k) {
        const double x = (k - 1) * run, z = z0 + k * rise;
        const double depth = k == tiers ? top_depth : run;
        sampleQuad(f.point(x, -width / 2, z), f.vec(depth, 0, 0), f.vec(0, width, 0), sp);
        sampleQuad(f.point(x, -width / 2, z - rise), f.vec(0, 0, rise), f.vec(0, width, 0), sp);
    }
}

void SceneBuilder::addWall(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double height) {
    const Eigen::Vector3d o(a.x(), a.y(), opt_.floor_z);
    const Eigen::Vector3d u(b.x() - a.x(), b.y() - a.y(), 0);
    sampleQuad(o, u, Eigen::Vector3d(0, 0, height), opt_.spacing_m);
}

}  // namespace stairmap::test
