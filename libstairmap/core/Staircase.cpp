#include "core/Staircase.h"

#include <cmath>

namespace stairmap {

double StairEdge::orientationRad() const {
    const Eigen::Vector3d d = end - start;
    double alpha = std::atan2(d.y(), d.x());
    // An edge has no direction: fold into (-pi/2, pi/2].
    if (alpha <= -M_PI / 2) alpha += M_PI;
    if (alpha > M_PI / 2) alpha -= M_PI;
    return alpha;
}

}  // namespace stairmap
