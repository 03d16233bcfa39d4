#pragma once
// Test helper: runs the built `stairmap` CLI and captures its exit code, stdout and stderr.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

namespace stairmap::testing {

struct CliResult {
    int exit_code = -1;
    std::string out, err;
};

inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline nlohmann::json readJson(const std::filesystem::path& path) {
    return nlohmann::json::parse(readText(path));
}

/// Fresh scratch directory for one test (removed first if a previous run left it). The process id
/// keeps parallel ctest processes of one suite (each re-running a shared SetUpTestSuite) apart.
inline std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::path(STAIRMAP_TEST_TMP) / "pipeline" /
                     (name + "." + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// Runs `stairmap <args>` (args are passed to /bin/sh as is; quote paths with spaces).
inline CliResult runStairmap(const std::string& args, const std::filesystem::path& log_dir) {
    const auto out = log_dir / "cli.stdout";
    const auto err = log_dir / "cli.stderr";
    const std::string cmd = std::string("'") + STAIRMAP_BIN + "' " + args + " > '" + out.string() +
                            "' 2> '" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = readText(out);
    r.err = readText(err);
    return r;
}

inline std::string datasetPath(const std::string& relative) {
    return std::string(STAIRMAP_SOURCE_DIR) + "/datasets/" + relative;
}

}  // namespace stairmap::testing
