#include "sim/BuildingGenerator.h"

#include <stdexcept>
#include <string>

#include "sim/StairGenerators.h"

namespace stairmap::sim {

namespace {
using V3 = Eigen::Vector3d;

void addBox(Scene& scene, const V3& min, const V3& max) { scene.add(makeAxisAlignedBox(min, max)); }

void addShell(Scene& scene, double h) {
    const double top = 2.0 * h;
    addFloor(scene, {-0.5, -0.5}, {24.5, 10.5}, 0.0);
    addBox(scene, {0, 0, 0}, {24, 0.2, top});
    addBox(scene, {0, 9.8, 0}, {24, 10, top});
    addBox(scene, {0, 0, 0}, {0.2, 10, top});
    addBox(scene, {23.8, 0, 0}, {24, 10, top});
}

/// Floor 1 slab around the two stairwell openings (x 1..top_a, y < 1.4 and x top_b..23, y > 8.6).
void addUpperFloor(Scene& scene, double h, double top_a_x, double top_b_x) {
    const double z0 = h - 0.2;
    addBox(scene, {0, 1.4, z0}, {24, 8.6, h});
    addBox(scene, {0, 0, z0}, {1.0, 1.4, h});
    addBox(scene, {top_a_x, 0, z0}, {24, 1.4, h});
    addBox(scene, {0, 8.6, z0}, {top_b_x, 10, h});
    addBox(scene, {23.0, 8.6, z0}, {24, 10, h});
}

/// Cross walls at x = 8 and x = 16 with a door at the corridor, and the corridor walls.
void addCorridor(Scene& scene, double z0, double z1, double y_min, double y_max) {
    for (double x : {8.0, 16.0}) {
        addBox(scene, {x - 0.1, 0.2, z0}, {x + 0.1, y_min, z1});
        addBox(scene, {x - 0.1, y_max, z0}, {x + 0.1, 9.8, z1});
    }
    addBox(scene, {8.0, y_min - 0.1, z0}, {16.0, y_min + 0.1, z1});
    addBox(scene, {8.0, y_max - 0.1, z0}, {16.0, y_max + 0.1, z1});
}

void addFurniture(Scene& scene, double h) {
    auto table = [&](double x, double y, double z) {
        addBox(scene, {x - 0.6, y - 0.4, z + 0.70}, {x + 0.6, y + 0.4, z + 0.74});
        for (double dx : {-0.55, 0.55})
            for (double dy : {-0.35, 0.35})
                addBox(scene, {x + dx - 0.03, y + dy - 0.03, z}, {x + dx + 0.03, y + dy + 0.03, z + 0.70});
    };
    table(4.5, 7.5, 0.0);
    table(19.5, 2.5, 0.0);
    table(4.0, 7.0, h);
    addBox(scene, {10.0, 8.0, h}, {11.5, 8.6, h + 1.8});  // cabinet on floor 1
    addBox(scene, {0.2, 5.0, 0.0}, {0.8, 6.5, 1.2});      // low cabinet on floor 0
}
}  // namespace

void validate(const BuildingParams& p) {
    auto require = [](bool ok, const char* field, const char* what) {
        if (!ok) throw std::invalid_argument(std::string(field) + ": " + what);
    };
    require(p.floor_height_m >= 2.0 && p.floor_height_m <= 5.0, "floor_height_m", "must be 2..5 m");
    require(p.num_risers >= 4 && p.num_risers <= 30, "num_risers", "must be 4..30");
    require(p.run_m >= 0.15 && p.run_m <= 0.4, "run_m", "must be 0.15..0.4 m (the hall is 24 m)");
    require(p.width_m >= 0.5 && p.width_m <= 1.2, "width_m", "must be 0.5..1.2 m");
    require(p.stair_b_run_m == 0.0 || (p.stair_b_run_m >= 0.15 && p.stair_b_run_m <= 0.4), "stair_b_run_m",
            "must be 0 (= run_m) or 0.15..0.4 m");
}

void addTwoFloorBuilding(Scene& scene, const BuildingParams& p) {
    validate(p);
    const double h = p.floor_height_m;
    StraightStairParams stair;
    stair.num_risers = p.num_risers;
    stair.rise_m = h / p.num_risers;
    stair.run_m = p.run_m;
    stair.width_m = p.width_m;
    stair.solid_landing = false;
    stair.landing_depth_m = 0.3;
    stair.wall_left = stair.wall_right = false;
    const double flight_a = (p.num_risers - 1) * p.run_m;
    const double run_b = p.stair_b_run_m > 0.0 ? p.stair_b_run_m : p.run_m;
    const double flight_b = (p.num_risers - 1) * run_b;

    stair.name = "stair_a";
    stair.origin = {2.0, 0.2 + 0.5 * p.width_m, 0.0};
    stair.heading_deg = 0.0;
    addStraightStair(scene, stair);
    stair.name = "stair_b";
    stair.origin = {22.0, 9.8 - 0.5 * p.width_m, 0.0};
    stair.heading_deg = 180.0;
    stair.run_m = run_b;
    addStraightStair(scene, stair);

    addShell(scene, h);
    addUpperFloor(scene, h, 2.0 + flight_a, 22.0 - flight_b);
    addCorridor(scene, 0.0, h - 0.2, 4.0, 6.0);
    addCorridor(scene, h, 2.0 * h, 3.0, 7.0);
    if (p.furniture) addFurniture(scene, h);
    scene.truth().floor_heights = {0.0, h};
}

}  // namespace stairmap::sim
