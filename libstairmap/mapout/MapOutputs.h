#pragma once
// The map outputs of a mapping run, written into its output folder: landmarks.json, map.bt,
// scene.3Dscene and overview.png, each replaced atomically (temp file, fsync, rename), so a kill
// at any moment leaves complete files. Shared by `stairmap map` (at the end) and `stairmap live`
// (at the end and on SIGUSR1), so both folders look the same to every reader (view, export,
// merge, --map-in).

#include <string>

#include "pipeline/Mapper.h"
#include "viz/MapScene.h"

namespace stairmap::mapout {

/// `dir`/`name`.
std::string outputPath(const std::string& dir, const std::string& name);

/// What the pictures show: the mapper's voxels, landmarks, floors and trajectory. Points into
/// `mapper` (valid while it lives and is not changed).
viz::MapView mapView(const pipeline::Mapper& mapper);

/// Writes landmarks.json, map.bt, scene.3Dscene and overview.png into `dir` (which must exist).
/// Throws std::runtime_error naming the file that could not be written (earlier files are
/// already replaced; the failed one keeps its previous content). Cost: O(voxels).
void writeMapOutputs(const pipeline::Mapper& mapper, const std::string& dir);

}  // namespace stairmap::mapout
