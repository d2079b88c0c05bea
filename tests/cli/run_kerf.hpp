// Runs the built kerf executable as a user would and captures its exit
// status and output, so CLI tests check the real command line contract.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <sys/wait.h>

struct KerfRun {
    int status = -1;
    std::string out, err;
};

inline std::filesystem::path test_dir(const std::string& name) {
    // Named after the build too: several checkouts may run these at once.
    const auto build = std::hash<std::string>{}(KERF_BINARY_DIR) % 1'000'000;
    auto dir = std::filesystem::temp_directory_path() / ("kerf_cli_" + std::to_string(build) + "_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string write_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

inline std::string slurp(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// `args` is appended to the command line verbatim (quote paths yourself).
// `prefix` runs before kerf in the same shell (see run_kerf_bounded);
// `input` is its standard input.
inline KerfRun run_kerf(const std::string& args, const std::filesystem::path& dir,
                        const std::string& prefix = "", const std::string& input = "/dev/null") {
    auto out = dir / "stdout.txt", err = dir / "stderr.txt";
    std::string cmd = prefix + std::string(KERF_BINARY_DIR) + "/kerf " + args + " >'" + out.string() +
                      "' 2>'" + err.string() + "' <'" + input + "'";
    int raw = std::system(cmd.c_str());
    KerfRun r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

// For hostile inputs: kerf runs under an address-space limit and a time
// limit, so a regression to runaway memory or a hang fails the test (status
// 124 from timeout, or bad_alloc's exit 3) instead of stalling the suite.
inline KerfRun run_kerf_bounded(const std::string& args, const std::filesystem::path& dir,
                                int seconds = 60, long memory_kb = 2'000'000) {
    return run_kerf(args, dir,
                    "ulimit -v " + std::to_string(memory_kb) + " && exec timeout " +
                        std::to_string(seconds) + " ");
}

inline std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }
