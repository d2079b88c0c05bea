// --stats reports resident memory and elapsed time at the end of each phase
// (cli/phase_memory.*, docs/performance.md "Memory"): every phase of a render
// in run order, the peak never falling, and a lowering that writes 10^5
// leaves raising it; the times never falling, and that lowering taking over
// a millisecond.
#include <catch2/catch.hpp>

#include <regex>
#include <vector>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("render --stats gives the peak and resident memory at the end of each phase") {
    auto dir = test_dir("stats_memory");
    // 10^5 spheres: their leaves alone are over 20 MB (sizeof(csg::Leaf) >= 200).
    const std::string scene = write_file(
        dir / "s.sdl", "for (i = [0:99], j = [0:99], k = [0:9]) translate([i, j, k]) sphere(0.3);\n");
    const auto r = run_kerf("render '" + scene + "' -o '" + (dir / "s.png").string() +
                                "' -W 16 -H 12 --threads 1 --stats --max-primitives 200000",
                            dir);
    REQUIRE(r.status == 0);
    std::smatch line;
    REQUIRE(std::regex_search(r.err, line, std::regex("stats: memory \\(peak so far / resident, MB\\) at the end of:(.*)\n")));
    const std::string marks = line[1];
    INFO(marks);
    std::vector<std::string> phases;
    std::vector<double> peak, resident;
    const std::regex mark(" ([a-z]+) ([0-9]+)/([0-9]+)");
    for (std::sregex_iterator it(marks.begin(), marks.end(), mark), end; it != end; ++it) {
        phases.push_back((*it)[1]);
        peak.push_back(std::stod((*it)[2]));
        resident.push_back(std::stod((*it)[3]));
    }
    CHECK(phases == std::vector<std::string>{"evaluate", "lower", "build", "trace", "write"});
    for (std::size_t i = 0; i < peak.size(); ++i) {
        CHECK(resident[i] <= peak[i]);
        if (i > 0) CHECK(peak[i] >= peak[i - 1]);
    }
    REQUIRE(peak.size() >= 2);
    CHECK(peak[1] >= peak[0] + 20);

    std::smatch times;
    REQUIRE(std::regex_search(r.err, times, std::regex("stats: time \\(ms since start-up\\) at the end of:(.*)\n")));
    const std::string tmarks = times[1];
    INFO(tmarks);
    std::vector<std::string> tphases;
    std::vector<double> ms;
    const std::regex tmark(" ([a-z]+) ([0-9]+\\.[0-9])");
    for (std::sregex_iterator it(tmarks.begin(), tmarks.end(), tmark), end; it != end; ++it) {
        tphases.push_back((*it)[1]);
        ms.push_back(std::stod((*it)[2]));
    }
    CHECK(tphases == phases);
    for (std::size_t i = 1; i < ms.size(); ++i) CHECK(ms[i] >= ms[i - 1]);
    REQUIRE(ms.size() == 5);
    CHECK(ms[0] > 0);
    CHECK(ms[1] - ms[0] >= 1);  // lowering 10^5 leaves takes a while (~50 ms)

    // Without --stats: no such line.
    const auto quiet = run_kerf("render '" + scene + "' -o '" + (dir / "q.png").string() +
                                    "' -W 16 -H 12 --threads 1 --max-primitives 200000",
                                dir);
    CHECK(quiet.err.find("stats: memory") == std::string::npos);
    CHECK(quiet.err.find("stats: time") == std::string::npos);
}
