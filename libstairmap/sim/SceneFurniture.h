#pragma once
// Small solids that make scenes look like buildings, as compositions of sim boxes and cylinders:
// railings, balusters, stringers, benches, tables, shelves. Each is given in a local frame T
// (x along the feature, y left, z up, z = 0 on the floor it stands on). Lengths in metres.

#include <Eigen/Geometry>

#include "sim/Scene.h"

namespace stairmap::sim {

/// Frame on the ground at `origin` whose x axis points along heading_deg (ccw from +x).
Eigen::Isometry3d groundFrame(const Eigen::Vector3d& origin, double heading_deg);

/// Box spanning min..max in frame T.
void addLocalBox(Scene& scene, const Eigen::Isometry3d& T, const Eigen::Vector3d& min,
                 const Eigen::Vector3d& max);

/// Straight bar from a to b (frame T) with a size_y x size_z cross-section; a to b must not be
/// parallel to T's y axis. Handrails, stringers, slanted beams.
void addBar(Scene& scene, const Eigen::Isometry3d& T, const Eigen::Vector3d& a,
            const Eigen::Vector3d& b, double size_y, double size_z);

/// Railing along the line from `a` to `b` (frame T, at walking height, e.g. the nosing line):
/// square posts about every post_spacing_m and a handrail `height_m` above the line.
void addRailing(Scene& scene, const Eigen::Isometry3d& T, const Eigen::Vector3d& a,
                const Eigen::Vector3d& b, double height_m = 0.9, double post_spacing_m = 1.0);

/// Vertical round baluster of radius 1.2 cm standing on (x, y, z) in frame T.
void addBaluster(Scene& scene, const Eigen::Isometry3d& T, const Eigen::Vector3d& foot,
                 double height_m = 0.9);

/// Bench along x: seat (length x depth) at seat_height with two end panels.
void addBench(Scene& scene, const Eigen::Isometry3d& T, double length, double depth,
              double seat_height);
/// Table centred on T's origin: top of length x depth at `height`, four legs.
void addTable(Scene& scene, const Eigen::Isometry3d& T, double length, double depth, double height);
/// Shelf along x against a wall: two side panels and `boards` boards 0.35-0.4 m apart.
void addShelf(Scene& scene, const Eigen::Isometry3d& T, double length, double depth, int boards);

}  // namespace stairmap::sim
