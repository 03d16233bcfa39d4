#include "replay/ViewFrameBuilder.h"

#include <algorithm>

namespace stairmap::replay {

viz::ViewFrame frameOf(const ReplaySession& session, int selected_id) {
    viz::ViewFrame f;
    const pipeline::Mapper& mapper = session.mapper();
    f.voxels = &mapper.voxelMap();
    if (session.lastScan()) {
        f.scan_robot = &session.lastScan()->points_robot;
        f.T_world_robot = session.lastScan()->T_world_robot;
    }
    f.landmarks = mapper.landmarks().staircases();
    f.floors = mapper.landmarks().floors();
    for (const auto& s : mapper.trajectory()) f.trajectory.push_back(s.position);
    if (session.lastRun()) {
        const RunSnapshot& run = *session.lastRun();
        viz::DetectorView d;
        d.T_world_grav = run.T_world_grav;
        d.radius_m = run.submap_radius_m;
        d.debug = &run.debug;
        for (const auto& r : run.records) d.detections_world.push_back(r.staircase_world);
        f.run = std::move(d);
    }
    f.robot_height_m = session.params().sensor.robot_height_m;
    f.selected_id = selected_id;
    return f;
}

viz::ViewFrame frameOf(const MapFolder& folder, double robot_height_m, int selected_id) {
    viz::ViewFrame f;
    if (folder.voxels) f.voxels = &*folder.voxels;
    f.T_world_robot = folder.last_pose;
    f.landmarks = folder.landmarks.staircases();
    f.floors = folder.landmarks.floors();
    f.trajectory = folder.trajectory;
    f.robot_height_m = robot_height_m;
    f.selected_id = selected_id;
    return f;
}

std::vector<int> landmarkIds(const viz::ViewFrame& frame) {
    std::vector<int> ids;
    for (const auto& l : frame.landmarks) ids.push_back(l.id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

}  // namespace stairmap::replay
