#pragma once
// Gathering `stairmap eval` inputs: detection files (the JSON printed by `stairmap detect`, or a
// landmarks.json from `stairmap map`) paired with their ground truth, or clouds to run the
// detector on. Pairing: X.json (or X.<anything>.json) goes with X.gt.json next to it unless a
// ground-truth file is given; a cloud X.pcd/.ply/.xyz goes with X.gt.json.

#include <optional>
#include <string>
#include <vector>

#include "core/Evaluation.h"

namespace stairmap::io {

/// Detection files found in `inputs` (files or directories; directories are scanned for *.json
/// that are not *.gt.json), sorted by name.
std::vector<std::string> findDetectionFiles(const std::vector<std::string>& inputs);

/// Clouds (*.pcd, *.ply, *.xyz) in `inputs` that have a sibling <stem>.gt.json, sorted by name.
/// Throws std::runtime_error naming an input that does not exist or a cloud without truth.
std::vector<std::string> findCloudsWithTruth(const std::vector<std::string>& inputs);

/// <dir>/<stem>.gt.json for a detection or cloud file.
std::string truthPathFor(const std::string& file);

/// Loads one detection file and its truth as an EvaluationSample. `gt_path` overrides the pairing.
/// Detect output gives time_ms; a landmark map (has "generator"/"continuation") has no time.
/// Throws std::runtime_error "<file>: problem".
EvaluationSample loadDetectionSample(const std::string& detection_path,
                                     const std::optional<std::string>& gt_path);

/// Kind label of a truth file: its top-level "kind", else its first staircase's kind, else
/// "negative".
std::string sampleKind(const std::string& gt_path);

}  // namespace stairmap::io
