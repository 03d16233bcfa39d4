#pragma once
// SplitMix64's finaliser: a well-mixed 64-bit value from any 64-bit input. Counter-based streams
// (a value from (seed, stream, index) alone, no state carried) are built on it: the random scene
// generator's draws (sim/RandomDraw) and the evaluation's perturbed realisations
// (CloudPerturbation).

#include <cstdint>

namespace stairmap {

inline std::uint64_t splitMix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

}  // namespace stairmap
