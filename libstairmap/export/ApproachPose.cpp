#include "export/ApproachPose.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace stairmap::exporting {
namespace {

bool insideRectangle(const Eigen::Vector2d& p, const Eigen::Vector2d& centre,
                     const Eigen::Vector2d& axis, double half_length, double half_width) {
    const Eigen::Vector2d d = p - centre;
    const Eigen::Vector2d across(-axis.y(), axis.x());
    return std::abs(d.dot(axis)) <= half_length && std::abs(d.dot(across)) <= half_width;
}

/// True if a cell of kind `wanted` has its centre inside the rectangle.
bool rectangleHas(const FloorGrid& grid, Cell wanted, const Eigen::Vector2d& centre,
                  const Eigen::Vector2d& axis, double half_length, double half_width) {
    const double reach = std::hypot(half_length, half_width);
    const double r = grid.resolution_m;
    const auto index = [r](double v, double origin) {
        return static_cast<int>(std::floor((v - origin) / r));
    };
    const int x0 = std::max(0, index(centre.x() - reach, grid.origin_x));
    const int y0 = std::max(0, index(centre.y() - reach, grid.origin_y));
    const int x1 = std::min(grid.width - 1, index(centre.x() + reach, grid.origin_x));
    const int y1 = std::min(grid.height - 1, index(centre.y() + reach, grid.origin_y));
    for (int iy = y0; iy <= y1; ++iy) {
        for (int ix = x0; ix <= x1; ++ix) {
            if (grid.at(ix, iy) != wanted) continue;
            if (insideRectangle(grid.cellCentre(ix, iy), centre, axis, half_length, half_width)) {
                return true;
            }
        }
    }
    return false;
}

/// Sideways offsets, nearest first: 0, +c, -c, +2c, -2c, ... up to `limit`.
std::vector<double> lateralOffsets(double cell, double limit) {
    std::vector<double> out = {0.0};
    for (double o = cell; o <= limit + 1e-9; o += cell) {
        out.push_back(o);
        out.push_back(-o);
    }
    return out;
}

}  // namespace

bool rectangleClear(const FloorGrid& grid, const Eigen::Vector2d& centre,
                    const Eigen::Vector2d& axis, double half_length, double half_width) {
    return !rectangleHas(grid, Cell::Occupied, centre, axis, half_length, half_width);
}

bool rectangleSeesFloor(const FloorGrid& grid, const Eigen::Vector2d& centre,
                        const Eigen::Vector2d& axis, double half_length, double half_width) {
    return rectangleHas(grid, Cell::Free, centre, axis, half_length, half_width);
}

ApproachPose findApproach(const FloorGrid* grid, const Eigen::Vector2d& edge_xy,
                          const Eigen::Vector2d& away, double floor_z, const RobotProfile& robot,
                          const ApproachParams& params) {
    const double cell = grid ? grid->resolution_m : 0.05;
    const double start = 0.5 * robot.footprint_length_m + robot.clearance_m + cell;
    const Eigen::Vector2d side(-away.y(), away.x());
    const auto poseAt = [&](double distance, double lateral) {
        ApproachPose pose;
        const Eigen::Vector2d xy = edge_xy + distance * away + lateral * side;
        pose.position = Eigen::Vector3d(xy.x(), xy.y(), floor_z);
        pose.yaw_rad = std::atan2(-away.y(), -away.x());
        return pose;
    };
    ApproachPose nearest = poseAt(start, 0.0);
    if (!grid || grid->width == 0) return nearest;
    const double half_length = 0.5 * robot.footprint_length_m + robot.clearance_m;
    const double half_width = 0.5 * robot.footprint_width_m + robot.clearance_m;
    const auto evaluate = [&](ApproachPose& pose) {
        const Eigen::Vector2d xy = pose.position.head<2>();
        pose.checked = true;
        pose.clear = rectangleClear(*grid, xy, away, half_length, half_width);
        pose.on_seen_floor = rectangleSeesFloor(*grid, xy, away, 0.5 * robot.footprint_length_m,
                                                0.5 * robot.footprint_width_m);
    };
    std::optional<ApproachPose> first_clear;
    const std::vector<double> laterals = lateralOffsets(cell, params.max_lateral_m);
    for (double d = start; d <= start + params.max_backoff_m + 1e-9; d += cell) {
        for (double lateral : laterals) {
            ApproachPose pose = poseAt(d, lateral);
            evaluate(pose);
            if (pose.clear && pose.on_seen_floor) return pose;
            if (pose.clear && !first_clear) first_clear = pose;
        }
    }
    if (first_clear) return *first_clear;
    evaluate(nearest);
    return nearest;
}

}  // namespace stairmap::exporting
