#pragma once
// What to draw (viz::ViewFrame) from a replay in progress or a finished map folder.

#include "replay/MapFolder.h"
#include "replay/ReplaySession.h"
#include "viz/ViewerScene.h"

namespace stairmap::replay {

/// The frame at session.position(): voxel map, current scan, landmarks, floors, trajectory and the
/// latest detector run. Pointers refer into `session` (valid until it advances).
viz::ViewFrame frameOf(const ReplaySession& session, int selected_id);

/// The finished map: voxels, landmarks, floors, trajectory; the robot at its last detection.
viz::ViewFrame frameOf(const MapFolder& folder, double robot_height_m, int selected_id);

/// Ascending ids of the landmarks of a frame (for Tab selection).
std::vector<int> landmarkIds(const viz::ViewFrame& frame);

}  // namespace stairmap::replay
