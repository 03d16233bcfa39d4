// The replay progress line: silent when disabled, ETA from the log's known duration.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <thread>

#include "io/system/ProgressBar.h"

namespace stairmap::io {
namespace {

TEST(ProgressBar, DisabledPrintsNothing) {
    std::ostringstream out;
    ProgressBar bar(out, false, 100.0);
    bar.update(10, 5.0);
    bar.finish();
    EXPECT_TRUE(out.str().empty());
}

TEST(ProgressBar, ShowsPercentOfLogAndEtaWhenDurationKnown) {
    std::ostringstream out;
    ProgressBar bar(out, true, 100.0);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    bar.update(25, 25.0);  // a quarter of a 100 s log
    const std::string line = out.str();
    EXPECT_NE(line.find("[ 25.0%]"), std::string::npos) << line;
    EXPECT_NE(line.find("25 scans"), std::string::npos) << line;
    EXPECT_NE(line.find("ETA"), std::string::npos) << line;
    bar.finish();
    EXPECT_EQ(out.str().back(), '\r');  // the line is cleared for what follows
}

TEST(ProgressBar, WithoutDurationShowsLogTimeAndNoEta) {
    std::ostringstream out;
    ProgressBar bar(out, true);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    bar.update(7, 3.5);
    EXPECT_NE(out.str().find("log 3.5 s"), std::string::npos) << out.str();
    EXPECT_EQ(out.str().find("ETA"), std::string::npos) << out.str();
}

}  // namespace
}  // namespace stairmap::io
