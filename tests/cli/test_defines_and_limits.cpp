// docs/spec.md §7–§8 command-line knobs through the real binary: -D values that do
// not parse or evaluate are a bad command line (exit 2, one line), and each
// limit flag moves its limit exactly (counts derived from the script).
#include "tests/cli/bad_input_checks.hpp"

namespace fs = std::filesystem;

TEST_CASE("a -D value that does not parse or evaluate is exit 2 with one line") {
    auto dir = test_dir("define_bad");
    const auto scene = write_file(dir / "d.sdl", "n = 1;\ncube(n);\n");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"n=1+", "-D n=1+: expected expression"},
        {"n=(", "-D n=(: expected expression"},
        {"n=[1,2", "-D n=[1,2: expected ']'"},
        {"n=", "-D n=: expected expression"},
        {"n=1;cube(2)", "-D n=1;cube(2): expected NAME=EXPRESSION"},
        {"1n=3", "-D 1n=3: expected statement"},
        {"n=undefined_x", "-D n=undefined_x: undefined name 'undefined_x'"},
        {"m=3", "-D m: the script has no top-level binding 'm'"},
    };
    for (const auto& [define, message] : cases) {
        for (const std::string command : {"check", "render"}) {
            const auto image = dir / "x.png";
            std::string args = command + " '" + scene + "' -D '" + define + "'";
            if (command == "render") args += " -W 8 -H 8 -o '" + image.string() + "'";
            const KerfRun r = run_kerf_bounded(args, dir);
            INFO(command << " -D " << define);
            CHECK(r.status == 2);
            CHECK(r.err == "<command line>: error: " + message + "\n");
            CHECK_FALSE(fs::exists(image));
        }
    }
    // Without '=' it is caught with the other options (and the usage follows).
    for (const std::string define : {"n", "=3"}) {
        const KerfRun r = run_kerf_bounded("check '" + scene + "' -D '" + define + "'", dir);
        CHECK(r.status == 2);
        CHECK(first_line(r.err) == "kerf: error: -D expects name=value, got '" + define + "'");
    }
}

TEST_CASE("a -D value that is fine but makes geometry non-finite is an error at the statement") {
    auto dir = test_dir("define_nan");
    const auto scene = write_file(dir / "d.sdl", "n = 1;\ncube(n);\n");
    expect_error(scene, dir, 2, 1, "cube: size must be finite, got inf", "-D n=1/0");
}

TEST_CASE("a deep or huge -D value ends in one short line") {
    auto dir = test_dir("define_huge");
    const auto scene = write_file(dir / "d.sdl", "n = 1;\ncube(n);\n");
    const std::string deep = "n=" + std::string(10'000, '(') + "1" + std::string(10'000, ')');
    KerfRun r = run_kerf_bounded("check '" + scene + "' -D '" + deep + "'", dir);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("<command line>: error: -D n=(((", 0) == 0);
    CHECK(r.err.find(": nesting deeper than 256\n") != std::string::npos);
    CHECK(r.err.size() < kMaxStderr);
    CHECK(count_of(r.err, "\n") == 1);

    // 100 KB: below the kernel's limit for one argument.
    r = run_kerf_bounded("check '" + scene + "' -D 'n=" + std::string(100'000, 'x') + "'", dir);
    CHECK(r.status == 2);
    CHECK(r.err == "<command line>: error: -D n=" + std::string(40, 'x') + "...: undefined name '" +
                       std::string(40, 'x') + "...'\n");
}

TEST_CASE("a good -D value overrides, and a $ variable needs no binding") {
    auto dir = test_dir("define_good");
    const auto scene = write_file(dir / "d.sdl", "n = 1;\nassert(len(n) == 3, \"n is not a vector\");\ncube(n);\n");
    CHECK(run_kerf_bounded("check '" + scene + "'", dir).status == 1);
    CHECK(run_kerf_bounded("check '" + scene + "' -D 'n=[1, 2, 3]'", dir).status == 0);
    CHECK(run_kerf_bounded("check '" + scene + "' -D 'n=[1, 2, 3]' -D '$fn=64'", dir).status == 0);
}

TEST_CASE("each limit flag moves its limit exactly") {
    auto dir = test_dir("limit_flags");
    // What each script needs, counted from its text: f(20) recurses 21 calls
    // deep; 10 parentheses, the 10th (column 4 + 10) crossing a limit of 9;
    // 200 iterations; 200 elements; 6 cubes. --max-steps: see the
    // exponential recursion in test_bad_evaluation.cpp.
    struct Limit {
        std::string flag, text;
        int needed, col;
        std::string message;
    };
    const std::vector<Limit> limits = {
        {"--max-call-depth", "function f(n) = n <= 0 ? 0 : 1 + f(n - 1);\na = f(20);\n", 21, 34,
         "call depth limit 20 exceeded"},
        {"--max-nesting", "a = ((((((((((1))))))))));\n", 10, 14, "nesting deeper than 9"},
        {"--max-iterations", "for (i = [1:200]) { }\n", 200, 6, "loop iteration limit 199 exceeded"},
        {"--max-list", "a = [for (i = [1:200]) i];\n", 200, 24, "list size limit 199 exceeded"},
        {"--max-primitives", "for (i = [1:6]) translate([i, 0, 0]) cube(1);\n", 6, 38, "primitive limit 5 exceeded"},
    };
    for (const auto& l : limits) {
        INFO(l.flag);
        const auto path = write_file(dir / "limit.sdl", l.text);
        CHECK(run_kerf_bounded("check '" + path + "' " + l.flag + " " + std::to_string(l.needed), dir).status == 0);
        expect_error(path, dir, 1, l.col, l.message, l.flag + " " + std::to_string(l.needed - 1));
    }
}

TEST_CASE("a limit flag without a whole positive number is exit 2") {
    auto dir = test_dir("limit_bad");
    const auto scene = write_file(dir / "ok.sdl", "cube(1);\n");
    for (const std::string flags :
         {"--max-call-depth 0", "--max-nesting x", "--max-steps -1", "--max-nesting 1e3", "--max-list"}) {
        const KerfRun r = run_kerf_bounded("check '" + scene + "' " + flags, dir);
        INFO(flags);
        CHECK(r.status == 2);
        CHECK(first_line(r.err).rfind("kerf: error: --max-", 0) == 0);
    }
}
