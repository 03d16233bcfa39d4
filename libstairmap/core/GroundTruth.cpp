#include "core/GroundTruth.h"

#include <array>
#include <utility>

namespace stairmap {

namespace {
const std::array<std::pair<StairKind, const char*>, 6> kKindNames = {{
    {StairKind::Ascending, "ascending"},
    {StairKind::Hollow, "hollow"},
    {StairKind::Spiral, "spiral"},
    {StairKind::Descending, "descending"},
    {StairKind::Debris, "debris"},
    {StairKind::Negative, "negative"},
}};
}  // namespace

std::string stairKindName(StairKind kind) {
    for (const auto& [k, name] : kKindNames) {
        if (k == kind) return name;
    }
    return "unknown";
}

std::optional<StairKind> stairKindFromName(const std::string& name) {
    for (const auto& [k, n] : kKindNames) {
        if (name == n) return k;
    }
    return std::nullopt;
}

SceneTruth transformTruth(const SceneTruth& truth, const Eigen::Isometry3d& T_b_a,
                          const std::string& frame_b) {
    SceneTruth out = truth;
    out.frame = frame_b;
    const double dz = T_b_a.translation().z();
    for (auto& stair : out.staircases) {
        for (auto& nosing : stair.nosings) {
            nosing.start = T_b_a * nosing.start;
            nosing.end = T_b_a * nosing.end;
        }
        stair.bottom_z += dz;
        stair.top_z += dz;
    }
    for (double& z : out.floor_heights) z += dz;
    if (out.observer_floor_z) *out.observer_floor_z += dz;
    return out;
}

}  // namespace stairmap
