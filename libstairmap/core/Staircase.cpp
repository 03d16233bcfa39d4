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

Eigen::Vector2d StairEdge::rhoTheta() const {
    const Eigen::Vector2d d = (end - start).head<2>();
    const double len = d.norm();
    // Degenerate edge: the normal is taken towards the point itself.
    Eigen::Vector2d n = len > 1e-12 ? Eigen::Vector2d(-d.y() / len, d.x() / len)
                                    : Eigen::Vector2d(1.0, 0.0);
    double rho = n.dot(start.head<2>());
    if (len <= 1e-12 && start.head<2>().norm() > 1e-12) {
        n = start.head<2>().normalized();
        rho = start.head<2>().norm();
    }
    if (rho < 0) {
        rho = -rho;
        n = -n;
    }
    return {rho, std::atan2(n.y(), n.x())};
}

const char* stairSideName(StairSide side) {
    switch (side) {
        case StairSide::Wall: return "wall";
        case StairSide::Open: return "open";
        case StairSide::Unseen: break;
    }
    return "unseen";
}

bool stairSideFromName(const std::string& name, StairSide& side) {
    for (StairSide s : {StairSide::Unseen, StairSide::Wall, StairSide::Open}) {
        if (name == stairSideName(s)) {
            side = s;
            return true;
        }
    }
    return false;
}

}  // namespace stairmap
