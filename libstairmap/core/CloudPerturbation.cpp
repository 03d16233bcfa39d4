#include "core/CloudPerturbation.h"

#include <cmath>
#include <stdexcept>

#include "core/SplitMix.h"

namespace stairmap {
namespace {

/// Uniform in [-1, 1) from the top 53 bits.
double unitOffset(std::uint64_t bits) {
    return static_cast<double>(bits >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

}  // namespace

void perturbCloud(PointCloud& cloud, double amplitude_m, std::uint64_t seed, std::uint64_t stream) {
    if (!(amplitude_m >= 0.0 && amplitude_m <= kMaxPerturbationM))
        throw std::invalid_argument("perturbation amplitude " + std::to_string(amplitude_m) +
                                    " m: must be in [0, " + std::to_string(kMaxPerturbationM) +
                                    "] m");
    if (amplitude_m == 0.0) return;
    // Counter-based: a point's offsets depend on its index alone, not on the points before it.
    const std::uint64_t base = splitMix64(splitMix64(seed) ^ stream);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t bits = splitMix64(base + 3 * static_cast<std::uint64_t>(i) + k);
            cloud[i][k] = static_cast<float>(cloud[i][k] + amplitude_m * unitOffset(bits));
        }
    }
}

std::uint64_t perturbationStream(const std::string& name) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const unsigned char c : name) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    return h;
}

}  // namespace stairmap
