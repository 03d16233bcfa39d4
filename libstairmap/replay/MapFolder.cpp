#include "replay/MapFolder.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "io/json/LandmarkJson.h"

namespace stairmap::replay {
namespace fs = std::filesystem;
namespace {

/// The robot pose of one detections.jsonl line ({"robot_pose": {"position", "quaternion_xyzw"}}).
Eigen::Isometry3d poseOf(const nlohmann::json& line) {
    const auto& pose = line.at("robot_pose");
    const auto p = pose.at("position").get<std::vector<double>>();
    const auto q = pose.at("quaternion_xyzw").get<std::vector<double>>();
    if (p.size() != 3 || q.size() != 4) throw std::runtime_error("robot_pose has wrong sizes");
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
    T.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
    return T;
}

void loadTrajectory(const std::string& path, MapFolder& folder) {
    std::ifstream in(path);
    if (!in) return;  // optional file
    std::string text;
    for (int line_no = 1; std::getline(in, text); ++line_no) {
        if (text.empty()) continue;
        try {
            const Eigen::Isometry3d T = poseOf(nlohmann::json::parse(text));
            if (folder.trajectory.empty() || (folder.trajectory.back() - T.translation()).norm() > 1e-6)
                folder.trajectory.push_back(T.translation());
            folder.last_pose = T;
        } catch (const std::exception& e) {
            throw std::runtime_error(path + ": line " + std::to_string(line_no) + ": " + e.what());
        }
    }
}

}  // namespace

bool isMapFolder(const std::string& dir) {
    std::error_code ec;
    return fs::is_directory(dir, ec) && fs::is_regular_file(fs::path(dir) / "landmarks.json", ec);
}

MapFolder loadMapFolder(const std::string& dir) {
    if (!isMapFolder(dir))
        throw std::runtime_error(dir + ": not a `stairmap map` output folder (no landmarks.json)");
    MapFolder folder{dir, io::loadLandmarkMap((fs::path(dir) / "landmarks.json").string()), {}, {},
                     {}};
    const fs::path bt = fs::path(dir) / "map.bt";
    if (fs::exists(bt)) folder.voxels = map::VoxelMap::load(bt.string());
    loadTrajectory((fs::path(dir) / "detections.jsonl").string(), folder);
    return folder;
}

}  // namespace stairmap::replay
