// A deliberately failing test (registered WILL_FAIL in tests/CMakeLists.txt): it checks that ctest
// counts the tests of a suite whose setup failed as failures, never as a pass or "Skipped".
// Before: SequenceRun's six tests showed up as Skipped when their SetUpTestSuite failed. gtest
// reports such tests as skipped; tests/NoSkips.cpp turns every skipped test into a failure.
#include <gtest/gtest.h>

namespace {

class SetupFails : public ::testing::Test {
protected:
    static void SetUpTestSuite() { FAIL() << "suite setup failed on purpose"; }
};

TEST_F(SetupFails, TestOfASuiteWhoseSetupFailed) { SUCCEED(); }

}  // namespace
