// Linked into every test executable: a test that ends skipped is failed instead.
//
// Why: gtest reports every test of a suite whose SetUpTestSuite failed as skipped (not failed),
// and ctest (gtest_discover_tests) counts "[  SKIPPED ]" as Skipped, which does not fail the
// run. So a broken setup hid as six skips. No stairmap test may pass by skipping, an explicit
// skip included. The listener sees each test's end before the result printer does (gtest calls
// OnTestEnd in reverse order of registration), while the test is still current, so the
// failure added here is what gets printed and counted. Regression test: tests/meta.
#include <gtest/gtest.h>

namespace {

class FailSkippedTests : public ::testing::EmptyTestEventListener {
    void OnTestEnd(const ::testing::TestInfo& info) override {
        if (info.result()->Skipped()) {
            ADD_FAILURE() << "skipped, which stairmap counts as a failure (did the suite's "
                             "SetUpTestSuite fail? see its messages above)";
        }
    }
};

const bool kRegistered = [] {
    ::testing::UnitTest::GetInstance()->listeners().Append(new FailSkippedTests);
    return true;
}();

}  // namespace
