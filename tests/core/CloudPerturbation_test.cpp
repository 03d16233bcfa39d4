#include "core/CloudPerturbation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace stairmap {
namespace {

/// Points on the random benchmark's 1/512 m lattice.
PointCloud latticeCloud(int n) {
    PointCloud cloud;
    for (int i = 0; i < n; ++i)
        cloud.emplace_back(static_cast<float>(i % 97) / 512.f, static_cast<float>(i % 89) / 512.f,
                           static_cast<float>(i % 13) / 512.f - 0.5f);
    return cloud;
}

TEST(CloudPerturbation, ZeroAmplitudeLeavesTheCloudAsItIs) {
    const PointCloud before = latticeCloud(1000);
    PointCloud after = before;
    perturbCloud(after, 0.0, 7, 11);
    EXPECT_EQ(after, before);
}

TEST(CloudPerturbation, OffsetsAreUniformWithinTheAmplitudeOnEveryAxis) {
    const double a = 1e-4;
    const PointCloud before = latticeCloud(30000);
    PointCloud after = before;
    perturbCloud(after, a, 1, perturbationStream("r0001_ascending.pcd.gz"));
    for (int k = 0; k < 3; ++k) {
        double sum = 0, sum2 = 0, largest = 0;
        int moved = 0;
        for (std::size_t i = 0; i < before.size(); ++i) {
            const double d = static_cast<double>(after[i][k]) - before[i][k];
            sum += d;
            sum2 += d * d;
            largest = std::max(largest, std::abs(d));
            moved += d != 0.0;
        }
        const double n = static_cast<double>(before.size());
        // float rounding of the moved coordinate adds at most half an ulp (3e-8 m at 0.5 m)
        EXPECT_LE(largest, a + 1e-7) << "axis " << k;
        EXPECT_GT(largest, 0.9 * a) << "axis " << k;
        EXPECT_GT(moved, 0.99 * n) << "axis " << k;
        // uniform on [-a, a]: mean 0 (standard error a / sqrt(3 n) = 3.3e-7), variance a^2 / 3
        EXPECT_NEAR(sum / n, 0.0, 2e-6) << "axis " << k;
        EXPECT_NEAR(sum2 / n, a * a / 3.0, 0.05 * a * a / 3.0) << "axis " << k;
    }
}

TEST(CloudPerturbation, TheSameSeedAndStreamGiveTheSameRealisation) {
    const PointCloud before = latticeCloud(500);
    PointCloud a = before, b = before, other_seed = before, other_stream = before;
    perturbCloud(a, 1e-5, 3, 42);
    perturbCloud(b, 1e-5, 3, 42);
    perturbCloud(other_seed, 1e-5, 4, 42);
    perturbCloud(other_stream, 1e-5, 3, 43);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, other_seed);
    EXPECT_NE(a, other_stream);
    // A point's offset depends on its index only: the first points of a longer cloud move alike.
    PointCloud longer = latticeCloud(800);
    perturbCloud(longer, 1e-5, 3, 42);
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(longer[i], a[i]) << i;
}

TEST(CloudPerturbation, NonFiniteCoordinatesStayNonFinite) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    PointCloud cloud{{nan, 0.f, 0.f}, {0.f, inf, 0.f}, {0.f, 0.f, -inf}};
    perturbCloud(cloud, 1e-3, 1, 1);
    EXPECT_TRUE(std::isnan(cloud[0].x()));
    EXPECT_EQ(cloud[1].y(), inf);
    EXPECT_EQ(cloud[2].z(), -inf);
}

TEST(CloudPerturbation, RefusesAmplitudesOutsideItsRange) {
    PointCloud cloud = latticeCloud(10);
    const PointCloud before = cloud;
    for (const double bad : {-1e-6, 0.011, 1.0, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
        EXPECT_THROW(perturbCloud(cloud, bad, 1, 1), std::invalid_argument) << bad;
        EXPECT_EQ(cloud, before) << bad;
    }
    EXPECT_NO_THROW(perturbCloud(cloud, kMaxPerturbationM, 1, 1));
}

TEST(CloudPerturbation, StreamsAreFnv1aOfTheName) {
    // The FNV-1a 64-bit test vectors (offset basis for the empty string).
    EXPECT_EQ(perturbationStream(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(perturbationStream("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(perturbationStream("foobar"), 0x85944171f73967e8ull);
}

}  // namespace
}  // namespace stairmap
