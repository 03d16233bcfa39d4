// Atomic output files: unique temp names per process and call, nothing left behind on errors,
// concurrent writers of one target never share a temp file.
#include "io/system/AtomicFile.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/system/AtomicOutputStream.h"

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

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::size_t fileCount(const std::string& dir) {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, TempNamesAreUniqueBesideTheTargetAndKeepTheExtension) {
    const std::string a = uniqueTempPath("/some/dir/overview.png");
    const std::string b = uniqueTempPath("/some/dir/overview.png");
    EXPECT_NE(a, b);
    EXPECT_EQ(fs::path(a).parent_path(), "/some/dir");
    EXPECT_EQ(fs::path(a).extension(), ".png");
    EXPECT_NE(a.find(std::to_string(::getpid())), std::string::npos) << a;
    EXPECT_TRUE(isTempFileName(fs::path(a).filename().string()));
    for (const char* name :
         {"overview.png", "landmarks.json.tmp", ".stairmap.lock", "a.tmp-x-1.json"})
        EXPECT_FALSE(isTempFileName(name)) << name;
}

TEST(AtomicFile, AFailingWriterLeavesThePreviousFileAndNoTempFile) {
    const std::string dir = scratch("failing");
    const std::string path = dir + "/map.bt";
    writeTextFileAtomic(path, "complete previous file");
    try {
        writeFileAtomic(path, [](const std::string& tmp) {
            std::ofstream(tmp) << "half of a";
            throw std::runtime_error("disk on fire");
        });
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": disk on fire", 0), 0u) << e.what();
    }
    EXPECT_THROW(writeFileAtomic(path,
                                 [](const std::string& tmp) {
                                     std::ofstream(tmp) << "half of b";
                                     throw std::bad_alloc();
                                 }),
                 std::runtime_error);
    EXPECT_EQ(readAll(path), "complete previous file");
    EXPECT_EQ(fileCount(dir), 1u);
    writeFileAtomic(path, [](const std::string& tmp) { std::ofstream(tmp) << "new"; });
    EXPECT_EQ(readAll(path), "new");
    EXPECT_EQ(fileCount(dir), 1u);
}

TEST(AtomicFile, ConcurrentWritersOfOneTargetNeverMixOrFail) {
    const std::string dir = scratch("concurrent");
    const std::string path = dir + "/landmarks.json";
    const std::string a(200000, 'a'), b(300000, 'b');
    pid_t children[2];
    for (int i = 0; i < 2; ++i) {
        children[i] = ::fork();
        ASSERT_GE(children[i], 0);
        if (children[i] == 0) {
            try {
                for (int k = 0; k < 40; ++k) writeTextFileAtomic(path, i == 0 ? a : b);
            } catch (...) {
                ::_exit(1);
            }
            ::_exit(0);
        }
    }
    for (pid_t child : children) {
        int status = 0;
        ::waitpid(child, &status, 0);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "a writer failed";
    }
    const std::string result = readAll(path);
    EXPECT_TRUE(result == a || result == b) << "mixed content of " << result.size() << " bytes";
    EXPECT_EQ(fileCount(dir), 1u);
}

TEST(AtomicFile, StaleTempFilesOfDeadProcessesAreSwept) {
    const std::string dir = scratch("stale");
    const pid_t dead = ::fork();
    if (dead == 0) ::_exit(0);
    ::waitpid(dead, nullptr, 0);
    const std::string stale = dir + "/.map.tmp-" + std::to_string(dead) + "-3.bt";
    const std::string mine = uniqueTempPath(dir + "/map.bt");
    std::ofstream(stale) << "x";
    std::ofstream(mine) << "x";
    std::ofstream(dir + "/map.bt") << "x";
    EXPECT_EQ(removeStaleTempFiles(dir), 1);
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(mine));
    EXPECT_TRUE(fs::exists(dir + "/map.bt"));
}

TEST(AtomicOutputStream, ReplacesTheTargetOnlyOnCommit) {
    const std::string dir = scratch("stream");
    const std::string path = dir + "/detections.jsonl";
    writeTextFileAtomic(path, "previous\n");
    {
        AtomicOutputStream out(path);
        out.stream() << "line 1\n";
        EXPECT_EQ(readAll(path), "previous\n");
        EXPECT_EQ(fileCount(dir), 2u);
    }  // destroyed without commit: an error path
    EXPECT_EQ(readAll(path), "previous\n");
    EXPECT_EQ(fileCount(dir), 1u);
    AtomicOutputStream out(path);
    out.stream() << "line 1\nline 2\n";
    out.commit();
    EXPECT_EQ(readAll(path), "line 1\nline 2\n");
    EXPECT_EQ(fileCount(dir), 1u);
    EXPECT_THROW(AtomicOutputStream(dir + "/missing/detections.jsonl"), std::runtime_error);
}

}  // namespace
}  // namespace stairmap::io
