#include "support/BenchmarkScenes.h"

#include <algorithm>
#include <cmath>

#include "sim/CloudSampler.h"

namespace stairmap::test {
namespace {

/// XY distance from p to the segment a-b.
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
    return (a + t * ab - p).norm();
}

/// XY distance from p to the nearest true nosing of `truth` whose height is within dz of z.
double distanceToNosings(const Eigen::Vector3d& p, const StaircaseTruth& truth, double dz) {
    double best = 1e9;
    for (const NosingSegment& n : truth.nosings) {
        if (std::abs(p.z() - n.start.z()) < dz)
            best = std::min(best, distanceToSegment(p.head<2>(), n.start.head<2>(), n.end.head<2>()));
    }
    return best;
}

}  // namespace

sim::RandomCloud benchmarkScene(int seed, int index) {
    sim::RandomCloud scene = sim::makeRandomCloud(static_cast<std::uint64_t>(seed), index);
    sim::quantizeAndSort(scene.cloud, 1.0 / 512.0, true);
    return scene;
}

bool reportsFlight(const Staircase& s, const StaircaseTruth& truth) {
    std::size_t near = 0;
    for (const StairEdge& e : s.steps) near += distanceToNosings(e.centre(), truth, 0.08) < 0.3 ? 1 : 0;
    return 2 * near >= s.steps.size();
}

}  // namespace stairmap::test
