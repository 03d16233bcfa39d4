// The per-object allocation cap behind guardedReadObject: requests through operator new and
// through MRPT's aligned allocator are refused before any memory is taken.
#include <gtest/gtest.h>

#include <mrpt/core/aligned_std_vector.h>
#include <mrpt/maps/CSimplePointsMap.h>

#include <string>
#include <vector>

#include "io/rawlog/AllocationBudget.h"

using stairmap::io::AllocationBudget;
using stairmap::io::AllocationBudgetExceeded;

constexpr std::uint64_t kMiB = std::uint64_t(1) << 20;

namespace {
// Allocates n bytes in a way the optimizer may not elide (new/delete pairs can be removed).
void allocate(std::size_t n) {
    std::vector<char> v(n);
    asm volatile("" : : "g"(v.data()) : "memory");
}
}  // namespace

TEST(AllocationBudget, RefusesAStringBeyondTheBudget) {
    AllocationBudget budget(16 * kMiB);
    std::string s;
    EXPECT_THROW(s.resize(64 * kMiB), AllocationBudgetExceeded);
    EXPECT_NO_THROW(s.resize(4 * kMiB));
    EXPECT_GE(budget.used(), 4 * kMiB);
}

TEST(AllocationBudget, RefusesMrptAlignedVectorsBeyondTheBudget) {
    AllocationBudget budget(16 * kMiB);
    mrpt::aligned_std_vector<float> v;
    EXPECT_THROW(v.resize(8 * kMiB), AllocationBudgetExceeded);  // 32 MiB
    mrpt::maps::CSimplePointsMap points;
    EXPECT_THROW(points.resize(2 * kMiB), AllocationBudgetExceeded);  // 3 x 8 MiB
}

TEST(AllocationBudget, CountsTheTotalNotTheLargestRequest) {
    AllocationBudget budget(10 * kMiB);
    std::vector<std::vector<char>> blocks;
    for (int i = 0; i < 4; ++i) blocks.emplace_back(2 * kMiB);  // 8 MiB in all
    EXPECT_THROW(blocks.emplace_back(3 * kMiB), AllocationBudgetExceeded);
}

TEST(AllocationBudget, MessageNamesTheRequest) {
    AllocationBudget budget(kMiB);
    try {
        allocate(5 * kMiB);
        FAIL() << "expected a refusal";
    } catch (const AllocationBudgetExceeded& e) {
        EXPECT_NE(std::string(e.what()).find(std::to_string(5 * kMiB) + " bytes refused"), std::string::npos)
            << e.what();
    }
}

TEST(AllocationBudget, NestedBudgetCannotExceedTheOuterOne) {
    AllocationBudget outer(4 * kMiB);
    AllocationBudget inner(64 * kMiB);
    EXPECT_THROW(allocate(8 * kMiB), AllocationBudgetExceeded);
}

TEST(AllocationBudget, NoCapOutsideABudgetOrWithZero) {
    { AllocationBudget limited(kMiB); }
    EXPECT_NO_THROW(allocate(32 * kMiB));
    AllocationBudget unlimited(0);
    EXPECT_NO_THROW(allocate(32 * kMiB));
}
