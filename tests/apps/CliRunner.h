#pragma once
// Runs the built `stairmap` binary (STAIRMAP_BIN) and captures exit code, stdout and stderr.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace stairmap::test {

struct CliResult {
    int exit_code = -1;
    std::string out;  ///< stdout
    std::string err;  ///< stderr
};

inline std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// A fresh, empty folder STAIRMAP_TEST_TMP/<suite>/<name>.
inline std::string cliScratchDir(const std::string& suite, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(STAIRMAP_TEST_TMP) / suite / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir.string();
}

/// Runs `stairmap <args>` (args are passed to the shell as written) with outputs in `dir`.
inline CliResult runStairmap(const std::string& args, const std::string& dir) {
    const std::string out = dir + "/stdout.txt", err = dir + "/stderr.txt";
    const std::string command = std::string("'") + STAIRMAP_BIN + "' " + args + " >'" + out + "' 2>'" + err + "'";
    const int status = std::system(command.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    r.out = readText(out);
    r.err = readText(err);
    return r;
}

}  // namespace stairmap::test
