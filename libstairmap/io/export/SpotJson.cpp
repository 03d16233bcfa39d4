#include "io/export/SpotJson.h"

#include <cmath>

namespace stairmap::io {
namespace {

nlohmann::json vec3(const Eigen::Vector3d& v) { return {{"x", v.x()}, {"y", v.y()}, {"z", v.z()}}; }

/// SE3Pose of a frame at `p` rotated by `yaw` about Z.
nlohmann::json se3(const Eigen::Vector3d& p, double yaw) {
    return {{"position", vec3(p)},
            {"rotation",
             {{"x", 0.0}, {"y", 0.0}, {"z", std::sin(0.5 * yaw)}, {"w", std::cos(0.5 * yaw)}}}};
}

nlohmann::json width(double w) {
    // Whether walls bound the flight is not measured.
    return {{"width", w}, {"bounded_width", "BOUNDED_WIDTH_UNKNOWN"}};
}

nlohmann::json landing(const exporting::SpotLanding& l) {
    return {{"stairs_tform_landing_center", se3(l.centre, 0.0)},
            {"landing_extent_x", l.extent_x_m},
            {"landing_extent_y", l.extent_y_m}};
}

}  // namespace

nlohmann::json spotStaircaseToJson(const exporting::SpotStaircase& s, const std::string& frame) {
    nlohmann::json steps = nlohmann::json::array();
    for (const auto& st : s.steps) {
        steps.push_back({{"point", vec3(st.point)},
                         {"north", {{"x", st.north.x()}, {"y", st.north.y()}}},
                         {"width", width(st.width_m)}});
    }
    nlohmann::json staircase = {
        {"knowledge_type", "KNOWLEDGE_TYPE_MAPPED"},
        {"stair_tform",
         {{"frame_tform_stairs", se3(s.origin_world, s.yaw_rad)}, {"frame_name", frame}}},
        {"average_rise", s.average_rise_m},
        {"average_run", s.average_run_m},
        {"average_width", width(s.average_width_m)},
        {"steps", steps},
        {"id", s.id}};
    return {{"bottom_landing", landing(s.bottom_landing)},
            {"staircase", staircase},
            {"top_landing", landing(s.top_landing)}};
}

nlohmann::json spotStaircasesToJson(const std::vector<exporting::SpotStaircase>& all,
                                    const std::string& frame) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& s : all) list.push_back(spotStaircaseToJson(s, frame));
    return {{"frame_name", frame}, {"generator", "stairmap export"}, {"staircases", list}};
}

}  // namespace stairmap::io
