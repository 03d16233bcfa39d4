#include "io/eval/EvalInputs.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/cloud/CloudFileFormat.h"
#include "io/json/GroundTruthJson.h"
#include "io/json/StaircaseJson.h"

namespace stairmap::io {

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool isCloud(const fs::path& p) {
    const CloudFileFormat f = cloudFileFormatOf(p.string());
    return f == CloudFileFormat::Pcd || f == CloudFileFormat::Ply || f == CloudFileFormat::Xyz;
}

json readJson(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open");
    try {
        json j;
        in >> j;
        return j;
    } catch (const json::exception& e) {
        throw std::runtime_error(path + ": not valid JSON (" + e.what() + ")");
    }
}

template <typename Keep>
std::vector<std::string> collect(const std::vector<std::string>& inputs, Keep keep) {
    std::vector<std::string> files;
    for (const auto& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            for (const auto& entry : fs::directory_iterator(input)) {
                if (entry.is_regular_file() && keep(entry.path())) files.push_back(entry.path().string());
            }
        } else if (fs::is_regular_file(input, ec)) {
            files.push_back(input);
        } else {
            throw std::runtime_error(input + ": no such file or directory");
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}
}  // namespace

std::string truthPathFor(const std::string& file) {
    const fs::path p(file);
    std::string stem = p.filename().string();
    stem = stem.substr(0, stem.find('.'));  // "ascending_0.det.json" -> "ascending_0"
    return (p.parent_path() / (stem + ".gt.json")).string();
}

std::vector<std::string> findDetectionFiles(const std::vector<std::string>& inputs) {
    return collect(inputs, [](const fs::path& p) {
        const std::string name = p.filename().string();
        return endsWith(name, ".json") && !endsWith(name, ".gt.json");
    });
}

std::vector<std::string> findCloudsWithTruth(const std::vector<std::string>& inputs) {
    auto clouds = collect(inputs, [](const fs::path& p) {
        return isCloud(p) && fs::exists(truthPathFor(p.string()));
    });
    for (const auto& c : clouds) {
        if (!isCloud(c))
            throw std::runtime_error(c + ": not a cloud file (.pcd, .ply, .xyz, each optionally .gz)");
        if (!fs::exists(truthPathFor(c))) throw std::runtime_error(c + ": no ground truth " + truthPathFor(c));
    }
    return clouds;
}

std::string sampleKind(const std::string& gt_path) {
    const json j = readJson(gt_path);
    if (j.contains("kind") && j["kind"].is_string()) return j["kind"].get<std::string>();
    const auto truth = groundTruthFromJson(j, gt_path);
    return truth.staircases.empty() ? "negative" : stairKindName(truth.staircases.front().kind);
}

std::string sampleLabel(const std::string& gt_path, const std::string& key) {
    if (key == "kind") return sampleKind(gt_path);
    const json j = readJson(gt_path);
    if (j.contains(key) && j[key].is_string()) return j[key].get<std::string>();
    return "unknown";
}

std::vector<std::pair<std::string, std::optional<std::string>>> pairDetectionFilesWithTruth(
    const std::vector<std::string>& inputs, const std::vector<std::string>& gt_paths) {
    std::vector<std::pair<std::string, std::optional<std::string>>> pairs;
    if (gt_paths.size() <= 1) {
        const std::optional<std::string> gt =
            gt_paths.empty() ? std::nullopt : std::optional<std::string>(gt_paths.front());
        for (const auto& file : findDetectionFiles(inputs)) pairs.emplace_back(file, gt);
        return pairs;
    }
    if (gt_paths.size() != inputs.size())
        throw std::runtime_error(std::to_string(gt_paths.size()) + " --gt files for " +
                                 std::to_string(inputs.size()) +
                                 " inputs (give one --gt for all inputs, or one per input)");
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        std::error_code ec;
        if (fs::is_directory(inputs[i], ec))
            throw std::runtime_error(inputs[i] + ": a directory cannot be paired with one --gt file");
        pairs.emplace_back(inputs[i], gt_paths[i]);
    }
    return pairs;
}

namespace {
/// Mean detector time per run [ms] from the stats.json next to a landmark map, if any.
std::optional<double> mapDetectorTimeMs(const std::string& map_path) {
    const fs::path stats = fs::path(map_path).parent_path() / "stats.json";
    if (!fs::exists(stats)) return std::nullopt;
    const json j = readJson(stats.string());
    const json* v = j.contains("stage_mean_ms") ? &j["stage_mean_ms"] : nullptr;
    if (v && v->contains("detect_per_run") && (*v)["detect_per_run"].is_number())
        return (*v)["detect_per_run"].get<double>();
    return std::nullopt;
}

bool isLandmarkMap(const json& j) { return j.contains("generator") || j.contains("continuation"); }
}  // namespace

EvaluationSample loadDetectionSample(const std::string& detection_path,
                                     const std::optional<std::string>& gt_path,
                                     const DetectionLoadOptions& options) {
    EvaluationSample sample;
    sample.name = fs::path(detection_path).filename().string();
    const std::string truth_path = gt_path ? *gt_path : truthPathFor(detection_path);
    if (!fs::exists(truth_path))
        throw std::runtime_error(detection_path + ": no ground truth (" + truth_path + " missing)");
    sample.truth = readGroundTruthFile(truth_path);
    sample.kind = sampleKind(truth_path);
    const json j = readJson(detection_path);
    if (!j.is_object() || !j.contains("staircases") || !j["staircases"].is_array())
        throw std::runtime_error(detection_path + ": no \"staircases\" array (not a detect/map output)");
    const bool map = isLandmarkMap(j);
    if (map) sample.name = detection_path;  // maps are all "landmarks.json": keep their folders
    try {
        for (const auto& s : j["staircases"]) {
            const bool confirmed = s.contains("confirmed") && s["confirmed"].is_boolean() &&
                                   s["confirmed"].get<bool>();
            if (map && options.confirmed_only && !confirmed) continue;
            sample.detections.push_back(staircaseFromJson(s));
        }
    } catch (const std::exception& e) {
        throw std::runtime_error(detection_path + ": " + e.what());
    }
    if (j.contains("time_ms") && j["time_ms"].is_number()) sample.time_ms = j["time_ms"].get<double>();
    if (map && !sample.time_ms) sample.time_ms = mapDetectorTimeMs(detection_path);
    return sample;
}

}  // namespace stairmap::io
