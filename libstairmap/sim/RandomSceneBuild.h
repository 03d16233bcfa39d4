#pragma once
// Builds a drawn random scene description into solids plus world truth (world = the robot's floor
// frame of RandomScene.h: robot at the origin, its floor at z = 0).

#include "sim/RandomScene.h"
#include "sim/Scene.h"

namespace stairmap::sim {

/// Solids of every flight and extra, floors at each level; truth with one staircase per flight
/// (named stair_0, stair_1, ...; kind from the family, a second flight is ascending) and the floor
/// heights. seen_as is left unset (the observation decides it, RandomCloud.h).
Scene buildRandomScene(const RandomSceneSpec& spec);

/// Negative features and furniture (RandomNegatives.cpp).
void addRandomExtra(Scene& scene, const NegativeSpec& extra, std::uint64_t seed, int index);

}  // namespace stairmap::sim
