// Deliberately failing tests (registered WILL_FAIL in tests/CMakeLists.txt): they check that
// ctest counts a failed suite setup and a GTEST_SKIP as failures, never as a pass or "Skipped".
// Before: SequenceRun's six tests showed up as Skipped when their SetUpTestSuite failed.
#include <gtest/gtest.h>

namespace {

class SetupFails : public ::testing::Test {
protected:
    static void SetUpTestSuite() { FAIL() << "suite setup failed on purpose"; }
};

TEST_F(SetupFails, TestOfASuiteWhoseSetupFailed) { SUCCEED(); }

TEST(Skipping, SkippedTest) { GTEST_SKIP() << "skipped on purpose"; }

}  // namespace
