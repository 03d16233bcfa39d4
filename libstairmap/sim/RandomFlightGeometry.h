#pragma once
// Where a drawn flight's solids go (shared by the generator, which keeps the robot and a second
// flight clear of them, and the builder). Frames as in RandomScene.h: robot at the origin, its
// floor at z = 0.

#include <Eigen/Geometry>

#include "sim/RandomScene.h"

namespace stairmap::sim {

constexpr double kTopLandingDepthM = 1.2;  ///< [m] landing beyond an ascending flight's last nosing

/// Straight flight frame: origin at the foot of the first riser, centre of the width, on the
/// flight's bottom floor; x up the flight. (For descending flights the top nosing is the edge at
/// distance_m / bearing_deg.)
Eigen::Isometry3d straightFlightFrame(const FlightSpec& f);

/// Spiral column axis at the robot's floor, and the angle [rad] of its first nosing.
Eigen::Vector3d spiralCentre(const FlightSpec& f);
double spiralStartAngle(const FlightSpec& f);
double spiralOuterRadius(const FlightSpec& f);

/// Extent of a straight flight's solids along its x axis that the robot must stay out of:
/// [front, back] in the flight frame (landings, lead-in steps, walls included).
double flightFrontX(const FlightSpec& f);
double flightBackX(const FlightSpec& f);

/// True if the robot (origin) can stand where it is: in front of an ascending flight (or beside
/// it when the flight rises from the robot's floor), behind a descending flight's top nosing.
bool robotClear(const FlightSpec& f);

/// True if the footprints (xy rectangles, with a margin [m]) of two straight flights overlap.
bool footprintsOverlap(const FlightSpec& a, const FlightSpec& b, double margin_m);

}  // namespace stairmap::sim
