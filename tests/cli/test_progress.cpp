// The progress line (docs/spec.md §7): on a terminal it names the phase and,
// while tracing, shows the time left; erased at the end; nothing at all
// when standard error is a file. The terminal is script(1)'s
// pseudo-terminal (util-linux, in every Debian system).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <regex>

#include "tests/cli/run_kerf.hpp"

namespace {

// Evaluation takes a few tenths of a second (an 8-million-element list:
// a 3-million one took ~150 ms, just the line's first-draw delay, and
// failed whenever evaluation ran faster), the trace about as long on one
// thread: long enough for both to be drawn.
const std::string kSlowScene =
    "big = [for (i = [0:8000000]) i * i];\n"
    "for (i = [0:30]) translate([i % 6 - 3, floor(i / 6) - 2, 0])\n"
    "    difference() { sphere(0.6 + big[i] * 0); cube(0.7, center = true); }\n";

}  // namespace

TEST_CASE("on a terminal the progress line shows the phase and, while tracing, the time left", "[progress]") {
    if (std::system("command -v script >/dev/null 2>&1") != 0) {
        WARN("script(1) is not installed: no pseudo-terminal to test with");
        return;
    }
    const auto dir = test_dir("progress_tty");
    const auto scene = write_file(dir / "slow.sdl", kSlowScene);
    const auto out = dir / "slow.png", tty = dir / "tty.txt";
    const std::string kerf = std::string(KERF_BINARY_DIR) + "/kerf render '" + scene + "' -W 1200 -H 900 --threads 1 -o '" +
                             out.string() + "'";
    const std::string cmd = "timeout 60 script -qec \"" + kerf + "\" /dev/null >'" + tty.string() + "' </dev/null";
    REQUIRE(std::system(cmd.c_str()) == 0);
    const std::string shown = slurp(tty);
    CHECK(shown.find("\r\033[Kevaluate ") != std::string::npos);
    // "trace    [#####        ]  42% 1.2s ETA 0.8s": a bar, the run's time, the time left.
    CHECK(std::regex_search(shown, std::regex("\r\033\\[Ktrace +\\[#* *\\] +[0-9]+% [0-9.]+s ETA [0-9.]+s")));
    // Erased when done: the last thing written is the erase.
    REQUIRE(shown.size() >= 4);
    CHECK(shown.compare(shown.size() - 4, 4, "\r\033[K") == 0);

    // --no-progress: nothing on the terminal either.
    const std::string quiet = "timeout 60 script -qec \"" + kerf + " --no-progress\" /dev/null >'" + tty.string() + "' </dev/null";
    REQUIRE(std::system(quiet.c_str()) == 0);
    CHECK(slurp(tty).empty());

    // The same render into a file: standard error stays empty.
    const KerfRun r = run_kerf("render '" + scene + "' -W 1200 -H 900 --threads 1 -o '" + out.string() + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
}
