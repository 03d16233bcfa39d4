#include "io/EvalInputs.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/GroundTruthJson.h"
#include "io/StaircaseJson.h"

namespace stairmap::io {

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool isCloud(const fs::path& p) {
    const std::string e = p.extension().string();
    return e == ".pcd" || e == ".ply" || e == ".xyz";
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
        if (!isCloud(c)) throw std::runtime_error(c + ": not a cloud file (.pcd, .ply, .xyz)");
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

EvaluationSample loadDetectionSample(const std::string& detection_path,
                                     const std::optional<std::string>& gt_path) {
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
    try {
        for (const auto& s : j["staircases"]) sample.detections.push_back(staircaseFromJson(s));
    } catch (const std::exception& e) {
        throw std::runtime_error(detection_path + ": " + e.what());
    }
    if (j.contains("time_ms") && j["time_ms"].is_number()) sample.time_ms = j["time_ms"].get<double>();
    return sample;
}

}  // namespace stairmap::io
