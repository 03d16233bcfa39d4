#pragma once
// Seeded draws for the random scene generator. The stream of scene `index` of set `seed` is
// independent of every other scene's (a SplitMix64 hash of the three numbers seeds it), so a set can
// be generated in any order or in parallel and scene i is the same in a set of 10 or 1000.

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "core/SplitMix.h"

namespace stairmap::sim {

class RandomDraw {
public:
    RandomDraw(std::uint64_t seed, std::uint64_t index, std::uint64_t stream)
        : rng_(splitMix64(splitMix64(splitMix64(seed) ^ index) ^ stream)) {}

    /// Uniform in [lo, hi] (lo when hi <= lo).
    double uniform(double lo, double hi) {
        if (!(hi > lo)) return lo;
        return lo + (hi - lo) * unit();
    }
    /// Uniform integer in [lo, hi].
    int integer(int lo, int hi) {
        if (hi <= lo) return lo;
        const double span = static_cast<double>(hi - lo + 1);
        return lo + std::min(hi - lo, static_cast<int>(unit() * span));
    }
    bool chance(double p) { return unit() < p; }
    /// Index drawn with probability proportional to weights[i].
    std::size_t pick(const std::vector<double>& weights) {
        double total = 0.0;
        for (double w : weights) total += w;
        double u = unit() * total;
        for (std::size_t i = 0; i < weights.size(); ++i) {
            if (u < weights[i]) return i;
            u -= weights[i];
        }
        return weights.size() - 1;
    }
    double gauss() { return normal_(rng_); }

private:
    /// Own mapping to [0, 1): std::uniform_real_distribution is not the same on every library.
    double unit() { return static_cast<double>(rng_() >> 11) * (1.0 / 9007199254740992.0); }
    std::mt19937_64 rng_;
    std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace stairmap::sim
