// docs/spec.md §8 malformed text through the real binary: truncated files, binary
// garbage, a 1 MB identifier, 10,000-deep nesting. Each ends in exit 1 and
// one located, short diagnostic (bad_input_checks.hpp), within the time and
// memory bounds of run_kerf_bounded.
#include <random>

#include "tests/cli/bad_input_checks.hpp"

namespace fs = std::filesystem;

namespace {

// A valid scene with every kind of construct a cut can land in.
const std::string kScene =
    "camera(position = [6, -9, 8], look_at = [0, 0, 0], fov = 40);\n"
    "light(position = [4, -6, 10], intensity = 1);\n"
    "/* a block\n"
    "   comment */\n"
    "s = 0.989227963463;\n"
    "label = \"shell\";\n"
    "module segment()\n"
    "    translate([3, 0, 0])\n"
    "    difference() {\n"
    "        sphere(1);\n"
    "        scale(s) translate([0, -0.02, 0]) sphere(1);\n"
    "    }\n"
    "for (k = [0:4]) scale(pow(0.979, k)) rotate([0, 0, 12 * k]) segment();\n";

// The scene up to and including the first occurrence of `marker`.
std::string cut_after(const std::string& marker) {
    const auto at = kScene.find(marker);
    REQUIRE(at != std::string::npos);
    return kScene.substr(0, at + marker.size());
}

// Line and byte column just past the end of `text`: where a parser that ran
// out of input must point.
std::pair<int, int> end_of(const std::string& text) {
    const int line = static_cast<int>(count_of(text, "\n")) + 1;
    const auto last_newline = text.rfind('\n');
    const std::size_t line_start = last_newline == std::string::npos ? 0 : last_newline + 1;
    return {line, static_cast<int>(text.size() - line_start) + 1};
}

std::string repeat(const std::string& s, int n) {
    std::string out;
    for (int i = 0; i < n; ++i) out += s;
    return out;
}

}  // namespace

TEST_CASE("the uncut scene is valid, so every cut below is what breaks it") {
    auto dir = test_dir("cut_whole");
    CHECK(run_kerf_bounded("check '" + write_file(dir / "whole.sdl", kScene) + "'", dir).status == 0);
}

TEST_CASE("a file cut in the middle of a construct is an error where the input ends") {
    auto dir = test_dir("cut_eof");
    const std::vector<std::pair<std::string, std::string>> cuts = {
        {"camera(position = [6, -9,", "expected expression"},
        {"camera(position = [6, -9, 8], look_at", "expected ')'"},
        {"s = 0.98", "expected ';'"},
        {"module segment()", "expected ';'"},  // the empty body is the first choice
        {"difference() {", "expected '}'"},
        {"        sphere(1);\n", "expected '}'"},
        {"scale(s) translate([0, -0.02", "expected ']'"},
        {"scale(pow(0.979, k)) rot", "expected '('"},
        {"12 * k]) segment()", "expected ';'"},
    };
    for (const auto& [marker, message] : cuts) {
        const std::string text = cut_after(marker);
        const auto path = write_file(dir / "cut.sdl", text);
        const auto [line, col] = end_of(text);
        INFO("cut after '" << marker << "'");
        expect_error(path, dir, line, col, message);
    }
}

TEST_CASE("a file cut inside a string or a block comment is an error where it opened") {
    auto dir = test_dir("cut_open");
    expect_error(write_file(dir / "string.sdl", cut_after("label = \"sh")), dir, 6, 9, "unterminated string");
    expect_error(write_file(dir / "comment.sdl", cut_after("/* a bl")), dir, 3, 1, "unterminated comment");
}

TEST_CASE("a file cut at any byte is valid or one located error, never a crash") {
    auto dir = test_dir("cut_sweep");
    int errors = 0;
    for (std::size_t n = 1; n < kScene.size(); n += 37) {
        const std::string text = kScene.substr(0, n);
        const auto path = write_file(dir / "cut.sdl", text);
        const KerfRun r = run_kerf_bounded("check '" + path + "'", dir);
        INFO("cut at byte " << n << "\n" << r.err);
        REQUIRE((r.status == 0 || r.status == 1));
        if (r.status == 0) {
            CHECK(r.err.empty());
            continue;
        }
        ++errors;
        const Located head = parse_head(first_line(r.err));
        CHECK(head.path == path);
        // Somewhere in the text, at the latest just past its end.
        const auto [end_line, end_col] = end_of(text);
        CHECK(head.line >= 1);
        CHECK((head.line < end_line || (head.line == end_line && head.col <= end_col)));
        CHECK(count_of(r.err, ": error: ") == 1);
    }
    CHECK(errors > 10);  // most cuts land mid-statement
}

TEST_CASE("seeded random bytes are one located error") {
    auto dir = test_dir("garbage_random");
    for (unsigned seed = 1; seed <= 4; ++seed) {
        std::mt19937 rng(seed);
        std::string bytes(4096, '\0');
        for (char& c : bytes) c = static_cast<char>(rng() & 0xFF);
        const auto path = write_file(dir / "random.sdl", bytes);
        INFO("seed " << seed);
        const Located head = reject(path, dir);
        const auto [end_line, end_col] = end_of(bytes);
        CHECK(head.line <= end_line);
    }
}

TEST_CASE("NUL bytes and invalid UTF-8 are located at the first bad byte, shown as '?'") {
    auto dir = test_dir("garbage_bytes");
    expect_error(write_file(dir / "nul.sdl", std::string(4096, '\0')), dir, 1, 1, "invalid character");
    expect_error(write_file(dir / "nul_after.sdl", std::string("cube(1);\nsphere(1);\0\0\0", 22)), dir, 2, 11,
                 "invalid character");
    // Lone continuation byte in a string, overlong '/', a UTF-16 surrogate,
    // a sequence cut by the end of the file.
    expect_error(write_file(dir / "cont.sdl", "label = \"a\x80z\";\n"), dir, 1, 11, "invalid character");
    expect_error(write_file(dir / "overlong.sdl", "x = 1;\n// \xC0\xAF\n"), dir, 2, 4, "invalid character");
    expect_error(write_file(dir / "surrogate.sdl", "x = 1; // \xED\xA0\x80\n"), dir, 1, 11, "invalid character");
    expect_error(write_file(dir / "cut_seq.sdl", "x = 1; // \xE2\x88"), dir, 1, 11, "invalid character");
    // Columns count bytes: the valid 3-byte '∓' before the bad byte counts 3.
    const auto path = write_file(dir / "after_utf8.sdl", "// \xE2\x88\x93 \xFF\n");
    expect_error(path, dir, 1, 8, "invalid character");

    // The source line is echoed with the bad byte as '?' (the valid UTF-8
    // character kept), and the caret counts characters, not bytes.
    const KerfRun r = run_kerf_bounded("check '" + path + "'", dir);
    CHECK(r.err == path + ":1:8: error: invalid character\n// \xE2\x88\x93 ?\n     ^\n");
}

TEST_CASE("a 1 MB identifier is not echoed back") {
    auto dir = test_dir("identifier");
    const std::string name(1'000'000, 'x');
    const std::string shown = std::string(40, 'x') + "...";

    const auto undefined = write_file(dir / "undefined.sdl", "cube(" + name + ");\n");
    expect_error(undefined, dir, 1, 6, "undefined name '" + shown + "'");
    const KerfRun r = run_kerf_bounded("check '" + undefined + "'", dir);
    // The source line is a window around the column, marked where it is cut.
    CHECK(r.err == undefined + ":1:6: error: undefined name '" + shown + "'\n" + "cube(" + std::string(100, 'x') +
                       "...\n     ^\n");

    expect_error(write_file(dir / "module.sdl", name + "(1);\n"), dir, 1, 1, "unknown module '" + shown + "'");

    const auto far = write_file(dir / "far.sdl", name + " 1;\n");
    expect_error(far, dir, 1, 1'000'002, "expected '('");
    const KerfRun f = run_kerf_bounded("check '" + far + "'", dir);
    CHECK(f.err == far + ":1:1000002: error: expected '('\n..." + std::string(99, 'x') + " 1;\n" +
                       std::string(103, ' ') + "^\n");

    // A long name is still a name.
    const auto fine = write_file(dir / "fine.sdl", name + " = 1;\ncube(" + name + ");\n");
    CHECK(run_kerf_bounded("check '" + fine + "'", dir).status == 0);
}

TEST_CASE("10,000-deep nesting stops at the nesting limit (256) where it is crossed") {
    auto dir = test_dir("nesting");
    const int n = 10'000;
    auto write = [&](const std::string& text) { return write_file(dir / "deep.sdl", text); };
    const std::string deeper = "nesting deeper than 256";
    // The 257th opening, after the 4 bytes of "a = ".
    expect_error(write("a = " + repeat("(", n) + "1" + repeat(")", n) + ";\n"), dir, 1, 4 + 257, deeper);
    expect_error(write("a = " + repeat("[", n) + "1" + repeat("]", n) + ";\n"), dir, 1, 4 + 257, deeper);
    expect_error(write("a = " + repeat("(", n) + "\n"), dir, 1, 4 + 257, deeper);  // never closed
    expect_error(write(repeat("{", n) + "cube(1);" + repeat("}", n) + "\n"), dir, 1, 257, deeper);
    expect_error(write(repeat("{\n", n) + "cube(1);\n" + repeat("}\n", n)), dir, 257, 1, deeper);
    // Nested calls: the '(' of the 257th f.
    expect_error(write("function f(x) = x;\na = " + repeat("f(", n) + "1" + repeat(")", n) + ";\n"), dir, 2,
                 4 + 2 * 256 + 2, deeper);
    // Nested module instantiations, built-in and user-defined: each level is
    // a statement plus its argument list, so the limit is met inside the
    // 256th translate's vector and at the 257th m's argument list.
    expect_error(write(repeat("translate([1, 0, 0]) ", n) + "cube(1);\n"), dir, 1, 21 * 255 + 11, deeper);
    expect_error(write("module m() children();\n" + repeat("m() ", n) + "cube(1);\n"), dir, 2, 4 * 256 + 2, deeper);
    // Unary operators nest too.
    expect_error(write("a = " + repeat("-", n) + "1;\n"), dir, 1, 4 + 257, deeper);
}

TEST_CASE("the nesting limit can be raised and 10,000-deep nesting then evaluates") {
    auto dir = test_dir("nesting_raised");
    const auto path = write_file(dir / "deep.sdl", "a = " + repeat("(", 10'000) + "1" + repeat(")", 10'000) + ";\n");
    const KerfRun r = run_kerf_bounded("check '" + path + "' --max-nesting 10001", dir);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
}

TEST_CASE("a 100,000-term operator chain stops at the chain limit, not the stack") {
    auto dir = test_dir("chain");
    const auto path = write_file(dir / "chain.sdl", "a = 1" + repeat(" + 1", 100'000) + ";\n");
    const Located head = reject(path, dir);
    CHECK(head.line == 1);
    CHECK(head.message == "expression deeper than 4096 (a chain of operators this long must be split)");
}

TEST_CASE("kerf dump rejects bad input exactly as kerf check does") {
    auto dir = test_dir("dump_bad");
    const std::vector<std::string> scripts = {
        std::string(64, '\0'),
        "a = " + repeat("(", 10'000) + "1;\n",
        "module m() m();\nm();\n",
        "cube([1, 0/0, 1]);\n",
    };
    for (const auto& text : scripts) {
        const auto path = write_file(dir / "bad.sdl", text);
        const KerfRun check = run_kerf_bounded("check '" + path + "'", dir);
        const KerfRun dump = run_kerf_bounded("dump '" + path + "'", dir);
        CHECK(check.status == 1);
        CHECK(dump.status == 1);
        CHECK(dump.out.empty());
        CHECK(dump.err == check.err);
        CHECK(parse_head(first_line(dump.err)).path == path);
    }
}
