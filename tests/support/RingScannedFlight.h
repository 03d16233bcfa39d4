#pragma once
// A closed-riser flight along +x on a floor, ray-cast by a level 16-ring LiDAR (rings 2 deg apart
// from -15 to 15 deg, a VLP-16) at the origin, and its edges as the top view finds them: the tests
// of the sparse-cloud corrections (RayClearance, StartSurface) share it.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/LineSegment.h"
#include "core/PointCloud.h"

namespace stairmap::test {

/// Nosing k at x0 + k run, height floor_z + (k + 1) rise; the floor below, a landing behind.
struct RingScannedFlight {
    double x0 = 4.0, run = 0.28, rise = 0.19, floor_z = -0.5;  ///< [m]
    int steps = 6;
    double nosingZ(int k) const { return floor_z + (k + 1) * rise; }
    double nosingX(int k) const { return x0 + k * run; }
    /// Height of the surface at horizontal distance x along the flight.
    double surface(double x) const {
        if (x < x0) return floor_z;
        const int k = std::min(steps - 1, static_cast<int>(std::floor((x - x0) / run)));
        return nosingZ(k);
    }
};

/// The first point where each ray (16 rings, azimuths +-6 deg every 0.2 deg) meets the flight's
/// profile (1 mm steps along the ground).
inline PointCloud scanFlight(const RingScannedFlight& f) {
    PointCloud cloud;
    for (int ring = 0; ring < 16; ++ring) {
        const double slope = std::tan((-15.0 + 2.0 * ring) * M_PI / 180.0);
        for (double az = -6.0; az <= 6.0; az += 0.2) {
            const double c = std::cos(az * M_PI / 180.0), s = std::sin(az * M_PI / 180.0);
            for (double r = 0.5; r < 12.0; r += 0.001) {
                const double x = r * c, z = slope * r;
                if (z <= f.surface(x)) {
                    cloud.emplace_back(x, r * s, z);
                    break;
                }
            }
        }
    }
    return cloud;
}

/// Edge k as the top view finds it: across the flight at the riser, at the height of the highest
/// point on riser k (a riser hit, below its nosing).
inline LineSegment riserTopEdge(const PointCloud& cloud, const RingScannedFlight& f, int k) {
    double top = -std::numeric_limits<double>::infinity();
    for (const auto& q : cloud)
        if (std::abs(q.x() - f.nosingX(k)) < 0.01 && std::abs(q.y()) < 0.45 && q.z() < f.nosingZ(k))
            top = std::max(top, static_cast<double>(q.z()));
    LineSegment l;
    l.start = {f.nosingX(k), -0.45};
    l.end = {f.nosingX(k), 0.45};
    l.z = top;
    l.rho = f.nosingX(k);
    l.num_points = 20;
    return l;
}

}  // namespace stairmap::test
