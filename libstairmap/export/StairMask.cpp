#include "export/StairMask.h"

#include <cmath>

namespace stairmap::exporting {

std::array<Eigen::Vector2d, 4> flightFootprint(const FlightGeometry& f) {
    const Eigen::Vector2d up = headingVector(f.heading_rad);
    const Eigen::Vector2d left(-up.y(), up.x());
    const Eigen::Vector2d b = f.bottom.head<2>(), t = f.top.head<2>();
    const double h = 0.5 * f.width_m;
    return {b - h * left, t - h * left, t + h * left, b + h * left};
}

FloorGrid stairMask(const FloorGrid& floor, const std::vector<FlightGeometry>& flights) {
    FloorGrid mask = floor;
    mask.cells.assign(floor.cells.size(), Cell::Free);
    for (const FlightGeometry& f : flights) {
        const Eigen::Vector2d up = headingVector(f.heading_rad);
        const Eigen::Vector2d left(-up.y(), up.x());
        const double length = (f.top - f.bottom).head<2>().dot(up);
        for (int iy = 0; iy < mask.height; ++iy) {
            for (int ix = 0; ix < mask.width; ++ix) {
                const Eigen::Vector2d d = mask.cellCentre(ix, iy) - f.bottom.head<2>();
                const double along = d.dot(up), across = d.dot(left);
                if (along >= 0.0 && along <= length && std::abs(across) <= 0.5 * f.width_m) {
                    mask.at(ix, iy) = Cell::Occupied;
                }
            }
        }
    }
    return mask;
}

}  // namespace stairmap::exporting
