// Runs the built kerf executable as a user would and captures its exit
// status and output, so CLI tests check the real command line contract.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

struct KerfRun {
    int status = -1;
    std::string out, err;
};

inline std::filesystem::path test_dir(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("kerf_cli_" + name);
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
inline KerfRun run_kerf(const std::string& args, const std::filesystem::path& dir) {
    auto out = dir / "stdout.txt", err = dir / "stderr.txt";
    std::string cmd = std::string(KERF_BINARY_DIR) + "/kerf " + args + " >'" + out.string() +
                      "' 2>'" + err.string() + "' </dev/null";
    int raw = std::system(cmd.c_str());
    KerfRun r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

inline std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }
