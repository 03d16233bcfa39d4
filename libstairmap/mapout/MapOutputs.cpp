#include "mapout/MapOutputs.h"

#include <filesystem>

#include "io/json/LandmarkJson.h"
#include "io/system/AtomicFile.h"
#include "viz/MapOverview.h"

namespace stairmap::mapout {

std::string outputPath(const std::string& dir, const std::string& name) {
    return (std::filesystem::path(dir) / name).string();
}

viz::MapView mapView(const pipeline::Mapper& mapper) {
    viz::MapView view;
    view.voxels = &mapper.voxelMap();
    view.staircases = mapper.landmarks().staircases();
    view.floors = mapper.landmarks().floors();
    for (const auto& s : mapper.trajectory()) view.trajectory.push_back(s.position);
    return view;
}

void writeMapOutputs(const pipeline::Mapper& mapper, const std::string& dir) {
    io::saveLandmarkMapAtomic(outputPath(dir, "landmarks.json"), mapper.landmarks());
    io::writeFileAtomic(outputPath(dir, "map.bt"),
                        [&](const std::string& p) { mapper.voxelMap().save(p); });
    const viz::MapView view = mapView(mapper);
    io::writeFileAtomic(outputPath(dir, "scene.3Dscene"),
                        [&](const std::string& p) { viz::saveMapScene(view, p); });
    io::writeFileAtomic(outputPath(dir, "overview.png"),
                        [&](const std::string& p) { viz::saveMapOverview(view, p); });
}

}  // namespace stairmap::mapout
