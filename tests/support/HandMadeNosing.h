#pragma once
// Hand-made nosing lines for the core tests that feed the chain search and its corrections.

#include "core/LineSegment.h"

namespace stairmap::test {

/// A seen nosing (20 points) across y in [-half_width, half_width] at distance x, height z [m]:
/// Hessian normal along +x, rho = x.
inline LineSegment nosingAcrossY(double x, double z, double half_width) {
    LineSegment l;
    l.start = {x, -half_width};
    l.end = {x, half_width};
    l.z = z;
    l.rho = x;
    l.theta = 0.0;
    l.num_points = 20;
    return l;
}

}  // namespace stairmap::test
