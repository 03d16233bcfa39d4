#pragma once
// `stairmap sim --random N --seed S --out DIR`: writes N random benchmark clouds (sim/RandomCloud.h)
// as <DIR>/r<index>_<family>.pcd.gz (robot frame, coordinates rounded to 2^-9 m, sorted) with
// <DIR>/r<index>_<family>.gt.json (truth in the same frame; "kind" = family, "sensor" = model,
// "sensor_kind", the drawn description under "scene_spec", "seen_nosings", "attempts").

#include <cstdint>
#include <functional>
#include <string>

namespace stairmap::io {

struct RandomSetOptions {
    std::uint64_t seed = 1;
    int count = 10;          ///< scenes 0..count-1
    int first_index = 0;     ///< index of the first scene
    int jobs = 1;            ///< worker threads (each scene is independent)
    std::function<void(const std::string&)> progress;  ///< one line per scene (may be empty)
};

struct RandomSetSummary {
    int clouds = 0;
    std::size_t points = 0;
    double generate_ms = 0.0;  ///< [ms] wall time of the whole set
    int redrawn = 0;           ///< scenes whose description was redrawn (half-visible flight)
};

/// Writes the set. Throws std::runtime_error naming the directory/file on I/O failure.
RandomSetSummary writeRandomSet(const std::string& out_dir, const RandomSetOptions& options);

}  // namespace stairmap::io
