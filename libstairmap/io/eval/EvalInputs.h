#pragma once
// Gathering `stairmap eval` inputs: detection files (the JSON printed by `stairmap detect`, or a
// landmarks.json from `stairmap map`) paired with their ground truth, or clouds to run the
// detector on. Pairing: X.json (or X.<anything>.json) goes with X.gt.json next to it unless a
// ground-truth file is given; a cloud X.pcd/.ply/.xyz (or X.pcd.gz ...) goes with X.gt.json.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/Evaluation.h"

namespace stairmap::io {

/// Detection files found in `inputs` (files or directories; directories are scanned for *.json
/// that are not *.gt.json), sorted by name.
std::vector<std::string> findDetectionFiles(const std::vector<std::string>& inputs);

/// Clouds (*.pcd, *.ply, *.xyz, each optionally gzipped: *.pcd.gz ...) in `inputs` that have a
/// sibling <stem>.gt.json, sorted by name.
/// Throws std::runtime_error naming an input that does not exist or a cloud without truth.
std::vector<std::string> findCloudsWithTruth(const std::vector<std::string>& inputs);

/// <dir>/<stem>.gt.json for a detection or cloud file.
std::string truthPathFor(const std::string& file);

/// How detection files are read.
struct DetectionLoadOptions {
    /// Landmark maps: score only landmarks with "confirmed": true (tentative ones are neither
    /// detections nor false positives). Detect outputs have no such flag and keep everything.
    bool confirmed_only = false;
};

/// Loads one detection file and its truth as an EvaluationSample. `gt_path` overrides the pairing.
/// Detect output gives time_ms; a landmark map gets the mean detector time per run from the
/// stats.json that `stairmap map` writes next to it (stage_mean_ms.detect_per_run), if present.
/// Throws std::runtime_error "<file>: problem".
EvaluationSample loadDetectionSample(const std::string& detection_path,
                                     const std::optional<std::string>& gt_path,
                                     const DetectionLoadOptions& options = {});

/// Pairs inputs with ground-truth files for `stairmap eval`: no gt -> each file's own
/// <stem>.gt.json (nullopt); one gt -> every input; n gts for n inputs -> the i-th input with the
/// i-th gt (inputs must then be files, not directories, so the order is the user's). Throws
/// std::runtime_error for any other count or a directory among paired inputs.
std::vector<std::pair<std::string, std::optional<std::string>>> pairDetectionFilesWithTruth(
    const std::vector<std::string>& inputs, const std::vector<std::string>& gt_paths);

/// Kind label of a truth file: its top-level "kind", else its first staircase's kind, else
/// "negative".
std::string sampleKind(const std::string& gt_path);

/// Table row of a truth file grouped by another top-level key (e.g. "sensor_kind" of the random
/// benchmark's gt.json): its string value, or "unknown" when absent; "kind" is sampleKind.
std::string sampleLabel(const std::string& gt_path, const std::string& key);

}  // namespace stairmap::io
