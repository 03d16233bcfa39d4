#pragma once
// Test helper: is each output of `stairmap map` complete and valid? Checked by format, not by
// comparing with an earlier run: a truncated file fails every check below.

#include <octomap/OcTree.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "ChildProcess.h"
#include "io/json/LandmarkJson.h"

namespace stairmap::test {

inline const std::vector<std::string>& mapOutputNames() {
    static const std::vector<std::string> names = {"landmarks.json",   "map.bt",
                                                   "detections.jsonl", "scene.3Dscene",
                                                   "overview.png",     "stats.json"};
    return names;
}

/// The OctoMap binary: its header's node count is the number of nodes its data holds.
inline std::string octomapProblem(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::size_t declared = 0;
    for (std::string line; std::getline(in, line) && line != "data";) {
        if (line.rfind("size ", 0) == 0) declared = std::stoul(line.substr(5));
    }
    octomap::OcTree tree(0.1);
    if (!tree.readBinary(path)) return "octomap cannot read it";
    if (declared == 0 || tree.size() != declared) {
        return "holds " + std::to_string(tree.size()) + " nodes of " + std::to_string(declared);
    }
    return "";
}

inline std::string pngProblem(const std::string& path) {
    const std::string bytes = fileText(path);
    const std::string signature("\x89PNG\r\n\x1a\n", 8);
    const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    if (bytes.compare(0, 8, signature) != 0) return "no PNG signature";
    if (bytes.size() < 20 || bytes.compare(bytes.size() - 12, 12, iend) != 0)
        return "no IEND chunk at the end";
    return "";
}

inline std::string jsonLinesProblem(const std::string& path) {
    const std::string text = fileText(path);
    if (!text.empty() && text.back() != '\n') return "last line incomplete";
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        if (!nlohmann::json::accept(line)) return "a line is not JSON: " + line.substr(0, 80);
    }
    return "";
}

/// "" if `dir/name` is a complete, valid output of its kind; else the problem.
inline std::string outputProblem(const std::filesystem::path& dir, const std::string& name) {
    const std::string path = (dir / name).string();
    if (!std::filesystem::is_regular_file(path)) return "missing";
    try {
        if (name == "landmarks.json") io::loadLandmarkMap(path);
        if (name == "stats.json" && !nlohmann::json::parse(fileText(path)).contains("scans"))
            return "no scans count";
    } catch (const std::exception& e) {
        return e.what();
    }
    if (name == "map.bt") return octomapProblem(path);
    if (name == "overview.png") return pngProblem(path);
    if (name == "detections.jsonl") return jsonLinesProblem(path);
    if (name == "scene.3Dscene" && std::system(("gzip -t '" + path + "' 2>/dev/null").c_str()) != 0)
        return "not a complete gzip stream";
    return "";
}

/// Every file in `dir` (names).
inline std::set<std::string> filesIn(const std::filesystem::path& dir) {
    std::set<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        names.insert(e.path().filename().string());
    return names;
}

}  // namespace stairmap::test
