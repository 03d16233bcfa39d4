// Fuzz target: TUM trajectories (`--poses`), then a pose lookup across the parsed span.
#include <sstream>
#include <stdexcept>

#include "FuzzInput.h"
#include "io/rawlog/TumTrajectory.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(stairmap::fuzz::asString(data, size));
    try {
        const auto trajectory = stairmap::io::TumTrajectory::read(in, "fuzz.tum");
        if (trajectory.empty()) return 0;
        const double t0 = trajectory.poses().front().stamp_s;
        const double t1 = trajectory.poses().back().stamp_s;
        for (int k = 0; k <= 4; ++k) {  // interpolation must give finite, rigid poses
            const auto pose = trajectory.poseAt(t0 + (t1 - t0) * k / 4.0, 0.01);
            if (pose && !pose->matrix().allFinite()) __builtin_trap();
        }
    } catch (const std::exception& e) {
        stairmap::fuzz::requireMessage(e);
    }
    return 0;
}
