// One run per output folder: the lock names its holder's pid and goes away with it.
#include "io/system/DirectoryLock.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace stairmap::io {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
    const fs::path dir =
        fs::path(STAIRMAP_TEST_TMP) / "io_system" / (name + "." + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

TEST(DirectoryLock, ASecondHolderIsRefusedNamingTheFirstsPid) {
    const std::string dir = scratch("lock");
    {
        const DirectoryLock lock(dir);
        EXPECT_TRUE(fs::exists(dir + "/.stairmap.lock"));
        // Another process tries: it must fail naming our pid and the folder.
        const pid_t child = ::fork();
        if (child == 0) {
            try {
                DirectoryLock second(dir);
            } catch (const std::runtime_error& e) {
                const std::string what = e.what();
                const bool named =
                    what.find("pid " + std::to_string(::getppid())) != std::string::npos &&
                    what.find(dir) != std::string::npos;
                ::_exit(named ? 0 : 2);
            }
            ::_exit(1);
        }
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_EQ(WEXITSTATUS(status), 0) << "1: second lock taken; 2: message lacks pid or folder";
    }
    EXPECT_FALSE(fs::exists(dir + "/.stairmap.lock")) << "released lock file left behind";
    const DirectoryLock again(dir);  // free again
}

TEST(DirectoryLock, ALockFileLeftByAKilledRunDoesNotBlock) {
    const std::string dir = scratch("stale_lock");
    std::ofstream(dir + "/.stairmap.lock") << "999999\n";  // no process holds it
    EXPECT_NO_THROW(DirectoryLock lock(dir));
}

TEST(DirectoryLock, AMissingFolderNamesTheLockFile) {
    try {
        DirectoryLock lock("/nonexistent/out");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/out/.stairmap.lock"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace stairmap::io
