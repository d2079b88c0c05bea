// --stats reports resident memory at the end of each phase (cli/phase_memory.*,
// docs/performance.md "Memory"): every phase of a render in run order, the
// peak never falling, and a lowering that writes 10^5 leaves raising it.
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

    // Without --stats: no such line.
    const auto quiet = run_kerf("render '" + scene + "' -o '" + (dir / "q.png").string() +
                                    "' -W 16 -H 12 --threads 1 --max-primitives 200000",
                                dir);
    CHECK(quiet.err.find("stats: memory") == std::string::npos);
}
