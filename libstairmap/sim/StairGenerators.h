#pragma once
// Parametric staircase generators. Each adds solids to a Scene and appends the staircase's ground
// truth (nosings bottom to top, see core/GroundTruth.h) to scene.truth().

#include <Eigen/Core>
#include <string>

#include "core/GroundTruth.h"
#include "sim/Scene.h"

namespace stairmap::sim {

/// Straight flight. Stair frame: origin at the foot of the first riser, centre of the width, on the
/// bottom floor; x points up the flight, z up. Covers ascending, descending (same solid, the
/// observer stands on the top landing), hollow (open risers, thin treads) and debris variants.
struct StraightStairParams {
    std::string name = "stair";
    StairKind kind = StairKind::Ascending;  ///< label only; open_risers/debris shape the solid
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< [m] world position of the frame origin
    double heading_deg = 0.0;        ///< [deg] direction of ascent, counter-clockwise from +x
    int num_risers = 8;              ///< risers from the bottom floor to the top landing
    double rise_m = 0.17;            ///< [m] riser height
    double run_m = 0.28;             ///< [m] tread depth
    double width_m = 1.2;            ///< [m] tread width
    bool open_risers = false;        ///< hollow stairs: thin floating treads, no risers
    double tread_thickness_m = 0.04; ///< [m] tread slab thickness when open_risers
    double landing_depth_m = 2.0;    ///< [m] top landing length beyond the last nosing
    bool solid_landing = true;       ///< landing is a block down to the bottom floor, else a slab
    double landing_thickness_m = 0.2;  ///< [m] landing slab thickness when not solid
    double landing_width_m = 0.0;    ///< [m] landing width (0: same as width_m)
    bool wall_left = true;           ///< side wall on the +y side of the flight
    bool wall_right = true;          ///< side wall on the -y side
    double wall_height_m = 1.0;      ///< [m] wall height above the top landing
    int debris_count = 0;            ///< random boxes lying on the treads
    double debris_max_size_m = 0.15; ///< [m] largest debris edge
    unsigned debris_seed = 1;
};

/// Spiral flight around a central column; ascends counter-clockwise unless `clockwise`.
struct SpiralStairParams {
    std::string name = "spiral";
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< [m] column axis at the bottom floor
    int num_risers = 12;
    double rise_m = 0.19;            ///< [m]
    double column_radius_m = 0.12;   ///< [m] treads start at the column
    double outer_radius_m = 1.1;     ///< [m] treads end here (width = outer - column radius)
    double step_angle_deg = 24.0;    ///< [deg] angle swept by one tread
    double start_angle_deg = 0.0;    ///< [deg] angle of the first nosing
    bool clockwise = false;
    double tread_thickness_m = 0.0;  ///< [m] 0: closed risers (each wedge one rise tall)
    double landing_angle_deg = 90.0; ///< [deg] sector of the top landing
    bool central_column = true;      ///< the solid column inside column_radius_m (false: a wide
                                     ///< spiral around an open well, the inner edge in the air)
};

/// Adds a straight flight; returns the index of its truth in scene.truth().staircases.
std::size_t addStraightStair(Scene& scene, const StraightStairParams& params);
std::size_t addSpiralStair(Scene& scene, const SpiralStairParams& params);

/// Adds a floor slab spanning [min_xy, max_xy] with its top at z [m] (thickness 0.1 m).
void addFloor(Scene& scene, const Eigen::Vector2d& min_xy, const Eigen::Vector2d& max_xy, double z);

/// Throw std::invalid_argument naming the field if a parameter is out of range.
void validate(const StraightStairParams& params);
void validate(const SpiralStairParams& params);

}  // namespace stairmap::sim
