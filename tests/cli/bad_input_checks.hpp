// What every hostile input must produce (docs/spec.md §8), checked through both
// `kerf check` and `kerf render`: exit 1 (not a signal, not the timeout's
// 124, not bad_alloc's 3), exactly one `PATH:LINE:COL: error: MESSAGE`
// diagnostic as the first line, a short standard error whatever the input's
// size, and no image written.
#pragma once
#include <catch2/catch.hpp>

#include <regex>

#include "tests/cli/run_kerf.hpp"

struct Located {
    std::string path;
    int line = 0, col = 0;
    std::string message;
};

inline Located parse_head(const std::string& line) {
    static const std::regex form(R"(^(.*):([0-9]+):([0-9]+): error: (.*)$)");
    std::smatch m;
    Located l;
    if (std::regex_match(line, m, form)) {
        l.path = m[1];
        l.line = std::stoi(m[2]);
        l.col = std::stoi(m[3]);
        l.message = m[4];
    }
    return l;
}

inline std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

// A diagnostic is three short lines (head, source line, caret); 1000 bytes
// leaves room for long paths while a 1 MB echo would be caught.
constexpr std::size_t kMaxStderr = 1000;

// What run_kerf_bounded allows each command.
struct Bounds {
    int seconds = 60;
    long memory_kb = 2'000'000;
};

// Runs both commands on `path` with extra `flags`; returns check's head
// (render's must be identical: it evaluates and lowers the same way).
inline Located reject(const std::string& path, const std::filesystem::path& dir, const std::string& flags = "",
                      const Bounds& bounds = {}) {
    Located check_head;
    std::string check_line;
    for (const std::string command : {"check", "render"}) {
        const auto image = dir / "must_not_exist.png";
        std::string args = command + " '" + path + "' " + flags;
        if (command == "render") args += " -W 16 -H 16 -o '" + image.string() + "'";
        const KerfRun r = run_kerf_bounded(args, dir, bounds.seconds, bounds.memory_kb);
        INFO("kerf " << args << "\nstderr: " << r.err.substr(0, 2 * kMaxStderr));
        CHECK(r.status == 1);
        const std::string line = first_line(r.err);
        const Located head = parse_head(line);
        CHECK(head.path == path);
        CHECK(head.line > 0);
        CHECK(head.col > 0);
        CHECK(count_of(r.err, ": error: ") == 1);
        CHECK(r.err.size() < kMaxStderr);
        CHECK_FALSE(std::filesystem::exists(image));
        if (command == "check") {
            check_head = head;
            check_line = line;
        } else {
            CHECK(line == check_line);
        }
    }
    return check_head;
}

inline void expect_error(const std::string& path, const std::filesystem::path& dir, int line, int col,
                         const std::string& message, const std::string& flags = "", const Bounds& bounds = {}) {
    const Located head = reject(path, dir, flags, bounds);
    CHECK(head.line == line);
    CHECK(head.col == col);
    CHECK(head.message == message);
}

// One script per row: written to dir/file, then expect_error().
struct BadScript {
    std::string file, text;
    int line = 0, col = 0;
    std::string message;
};

inline void expect_errors(const std::filesystem::path& dir, const std::vector<BadScript>& scripts) {
    for (const auto& s : scripts) {
        INFO(s.file << ": " << s.text.substr(0, 200));
        expect_error(write_file(dir / s.file, s.text), dir, s.line, s.col, s.message);
    }
}
