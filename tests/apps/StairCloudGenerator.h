#pragma once
// Test-side generator of a straight staircase cloud with KNOWN geometry for the CLI end-to-end tests.
// Independent of the detector: samples the visible surfaces (floors, treads, risers) on a jittered
// grid with seeded isotropic Gaussian noise. Robot frame: x forward, y left, z up, floor z = -H.

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "core/PointCloud.h"

namespace stairmap::test {

struct StairCloudSpec {
    bool ascending = true;
    int num_risers = 6;
    double rise_m = 0.17;
    double run_m = 0.29;
    double width_m = 1.1;
    double distance_m = 2.0;     ///< [m] robot -> first nosing (descending: the floor's edge)
    double yaw_rad = 0.0;        ///< direction of travel up (ascending) / down (descending)
    double robot_height_m = 0.6; ///< floor at z = -robot_height_m
    double noise_m = 0.01;       ///< [m] std. dev. of the Gaussian noise on each coordinate
    double spacing_m = 0.02;     ///< [m] sample spacing on stair surfaces (floors: 1.5x)
    unsigned seed = 1;
};

struct StairCloudTruth {
    std::vector<Eigen::Vector3d> nosing_centres;  ///< from the robot's floor outward
    Eigen::Vector3d location = Eigen::Vector3d::Zero();  ///< centre of the first nosing
};

class StairCloudGenerator {
public:
    explicit StairCloudGenerator(const StairCloudSpec& spec) : s_(spec), rng_(spec.seed) {}

    /// Ascending: floor, then risers and treads, the last tread being the upper floor (1 m deep).
    /// Descending: the robot's floor with a stairwell cut out, treads going down (risers face away
    /// from the robot and are not sampled), then the lower floor (1.5 m deep).
    PointCloud generate(StairCloudTruth& truth) {
        const double z0 = -s_.robot_height_m, w = s_.width_m, d = s_.distance_m, r = s_.run_m;
        const int n = s_.num_risers;
        // The robot's floor reaches exactly as far as the last tread/landing, so it does not end
        // in mid-air beside the flight (an edge-like artefact no real scene has).
        const double last_depth = s_.ascending ? 1.0 : 1.5;  // upper landing / lower floor
        const double far = d + (n - 1) * r + last_depth;
        quad({-3, -3, z0}, {far + 3, 0, 0}, {0, 6, 0}, 1.5, true);
        for (int k = 0; k < n; ++k) {
            const double x = d + k * r;  // nosing k, stair frame
            const double depth = k + 1 < n ? r : last_depth;
            if (s_.ascending) {
                const double z = z0 + (k + 1) * s_.rise_m;
                quad({x, -w / 2, z - s_.rise_m}, {0, w, 0}, {0, 0, s_.rise_m}, 1.0, false);  // riser k
                quad({x, -w / 2, z}, {depth, 0, 0}, {0, w, 0}, 1.0, false);                  // tread k
                truth.nosing_centres.push_back(toRobot(x, 0, z));
            } else {
                const double z = z0 - (k + 1) * s_.rise_m;  // tread below nosing k
                quad({x, -w / 2, z}, {depth, 0, 0}, {0, w, 0}, 1.0, false);
                truth.nosing_centres.push_back(toRobot(x, 0, z0 - k * s_.rise_m));
            }
        }
        truth.location = truth.nosing_centres.front();
        return std::move(cloud_);
    }

private:
    Eigen::Vector3d toRobot(double x, double y, double z) const {
        const double c = std::cos(s_.yaw_rad), sn = std::sin(s_.yaw_rad);
        return {c * x - sn * y, sn * x + c * y, z};
    }

    /// Samples origin + a*u + b*v (stair frame), a, b in [0, 1]; `floor` skips the stair footprint.
    void quad(const Eigen::Vector3d& o, const Eigen::Vector3d& u, const Eigen::Vector3d& v, double spacing_factor,
              bool floor) {
        const double spacing = s_.spacing_m * spacing_factor;
        const int nu = std::max(1, int(std::ceil(u.norm() / spacing)));
        const int nv = std::max(1, int(std::ceil(v.norm() / spacing)));
        std::uniform_real_distribution<double> jitter(0.0, 1.0);
        std::normal_distribution<double> noise(0.0, s_.noise_m);
        for (int i = 0; i < nu; ++i) {
            for (int j = 0; j < nv; ++j) {
                const Eigen::Vector3d p = o + (i + jitter(rng_)) / nu * u + (j + jitter(rng_)) / nv * v;
                if (floor && p.x() >= s_.distance_m && std::abs(p.y()) <= s_.width_m / 2 + 0.02) continue;
                const Eigen::Vector3d q = toRobot(p.x(), p.y(), p.z());
                cloud_.emplace_back(float(q.x() + noise(rng_)), float(q.y() + noise(rng_)), float(q.z() + noise(rng_)));
            }
        }
    }

    StairCloudSpec s_;
    std::mt19937 rng_;
    PointCloud cloud_;
};

}  // namespace stairmap::test
