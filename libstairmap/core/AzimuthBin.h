#pragma once
// Azimuth bin of a point around the robot, for the cylindrical organisation (paper Sec. III-A).
// std::atan2 costs ~25 ns here and runs once per nosing candidate (~12k per 60k-point cloud, a
// fifth of a detection), so a polynomial decides the bin and std::atan2 is consulted only near a
// bin boundary: the result is the same bin std::atan2 would give.

#include <algorithm>
#include <cmath>

namespace stairmap {

/// atan2 to within 2e-6 rad: an odd degree-11 polynomial for atan on [0, 1] (coefficients fitted
/// for this project by iteratively reweighted least squares towards the minimax error) plus
/// octant folding.
inline float approxAtan2(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float hi = std::max(ax, ay);
    if (hi == 0.f) return 0.f;
    const float a = std::min(ax, ay) / hi, s = a * a;
    float r =
        0.999977223f +
        s * (-0.332622912f +
             s * (0.193540896f + s * (-0.116427746f + s * (0.0526486605f - s * 0.0117196190f))));
    r *= a;
    if (ay > ax) r = 1.57079637f - r;
    if (x < 0.f) r = 3.14159274f - r;
    return y < 0.f ? -r : r;
}

/// Maps angles in [-pi, pi] to `bins` equal bins: floor((atan2(y, x) + pi) * bins / (2 pi)),
/// clamped to [0, bins - 1], evaluated in float exactly like that expression with std::atan2.
class AzimuthBinner {
  public:
    explicit AzimuthBinner(int bins)
        : bins_(bins),
          scale_(static_cast<float>(bins / (2 * M_PI))),
          // approximation error (2e-6 rad, with a wide safety factor) plus float rounding of the
          // bin coordinate, in bins
          margin_(static_cast<float>(2.5e-5 * bins / (2 * M_PI)) + 4e-4f) {}

    int operator()(float x, float y) const {
        const float f = (approxAtan2(y, x) + static_cast<float>(M_PI)) * scale_;
        // f >= 0 (up to rounding), so truncation is floor; std::floor is a libm call without SSE4.1
        const float frac = f - static_cast<float>(static_cast<int>(f));
        if (frac < margin_ || frac > 1.f - margin_) return exact(x, y);  // near a boundary
        return std::clamp(static_cast<int>(f), 0, bins_ - 1);
    }

    int exact(float x, float y) const {
        const int bin = static_cast<int>((std::atan2(y, x) + static_cast<float>(M_PI)) * scale_);
        return std::clamp(bin, 0, bins_ - 1);
    }

  private:
    int bins_;
    float scale_;
    float margin_;
};

}  // namespace stairmap
