#pragma once
// A small but complete landmark map (several flights on three floors, a joined landmark, robot
// floor samples) and a scratch folder, shared by the persistence tests.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "map/LandmarkMap.h"
#include "core/SyntheticStairs.h"

namespace stairmap::test {

inline std::vector<FlightTruth> buildingFlights() {
    FlightTruth a;
    a.num_steps = 18;
    a.origin_xy = {2.0, 1.0};
    a.heading_rad = 0.3;
    FlightTruth b = a;  // stacked one floor up
    b.floor_z = a.topZ();
    FlightTruth c = a;  // a second stairwell on the ground floor
    c.origin_xy = {15.0, -4.0};
    c.heading_rad = -2.2;
    return {a, b, c};
}

/// Detections of every flight from varied partial views, ascending and descending.
inline std::vector<Staircase> robotDetections(unsigned seed, bool second_robot = false) {
    std::mt19937 rng(seed);
    std::vector<Staircase> out;
    for (const FlightTruth& f : buildingFlights()) {
        for (int k = 0; k < 4; ++k) {
            ViewSpec v;
            v.first = second_robot ? 2 * k : k;
            v.last = second_robot ? f.num_steps - 1 : f.num_steps - 1 - 2 * k;
            v.descending = second_robot ? (k % 2 == 0) : (k % 2 == 1);
            v.crop_left = second_robot ? 0.3 : 0.0;
            v.drift = second_robot ? Eigen::Vector3d(0.02, -0.02, 0.01) : Eigen::Vector3d::Zero();
            v.sigma_perp = 0.01;
            v.sigma_theta = 0.01;
            v.sigma_z = 0.01;
            v.sigma_end = 0.02;
            out.push_back(makeDetection(f, v, rng));
        }
    }
    return out;
}

inline LandmarkMap buildTestMap() {
    LandmarkParams params;
    params.use_footprint = false;  // so that two partial views of one flight start apart
    params.max_extrapolated_steps = 0;
    LandmarkMap map(params);
    std::mt19937 rng(99);
    const std::vector<FlightTruth> flights = buildingFlights();
    for (double z : {0.0, flights[0].topZ(), flights[1].topZ()}) {
        for (int i = 0; i < 12; ++i) map.addRobotFloor(z + 0.001 * i, i);
    }
    ViewSpec low;
    low.last = 3;
    ViewSpec high;
    high.first = 12;
    map.addDetection(makeDetection(flights[0], low, rng), 1.0);
    map.addDetection(makeDetection(flights[0], high, rng), 2.0);  // a second landmark ...
    double t = 3.0;
    for (const Staircase& d : robotDetections(5)) map.addDetection(d, t++);  // ... joined here
    return map;
}

/// A fresh folder for one test. The pid keeps tests that ctest runs in parallel processes apart
/// (two of them sharing "schema" removed each other's files).
inline std::string scratchDir(const std::string& name) {
    const std::string dir =
        std::string(STAIRMAP_TEST_TMP) + "/landmarks/" + name + "." + std::to_string(::getpid());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeFile(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

}  // namespace stairmap::test
