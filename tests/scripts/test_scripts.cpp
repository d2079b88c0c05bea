// The golden scripts: every tests/scripts/**/*.sdl and *.scad (the
// OpenSCAD dialect, chosen by the extension) is evaluated and lowered
// (what `kerf check` does) and its output compared with the expectations in
// its comments (expectations.hpp). A script without `// error:` must run
// without one; a script without `// ECHO:` must print nothing.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "lower/geometry_ops.hpp"
#include "lower/lower.hpp"
#include "tests/fuzz/fuzz_limits.hpp"
#include "tests/scripts/expectations.hpp"

using namespace kerf;

namespace {

const std::string kRoot = KERF_SOURCE_DIR "/";

std::vector<std::string> script_paths() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(kRoot + "tests/scripts"))
        if (e.is_regular_file() && (e.path().extension() == ".sdl" || e.path().extension() == ".scad"))
            out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("golden scripts do what their comments say", "[scripts]") {
    static const std::vector<std::string> paths = script_paths();
    REQUIRE(paths.size() >= 40);
    const std::string path = GENERATE(from_range(paths));
    INFO(path.substr(kRoot.size()));
    const test::Expectations want = test::expectations_of(read_all(path));

    EvalOptions opt;
    opt.resolve_geometry_ops = resolve_geometry_ops;  // as the CLI: projection() of a hull
    if (want.fuzz_limits) opt.limits = test::fuzz_limits();
    REQUIRE((want.facets == "auto" || want.facets == "exact" || want.facets == "openscad"));
    opt.facets = want.facets == "exact" ? FacetMode::Exact : want.facets == "openscad" ? FacetMode::OpenScad : FacetMode::Auto;
    std::vector<std::string> echoed;
    opt.echo = [&](const std::string& line) { echoed.push_back(line); };
    std::vector<std::string> warnings, notes, errors;
    auto add_notes = [&](const Diagnostic& d) {
        for (const Diagnostic& n : d.notes) notes.push_back(test::expectation_text(n, path, kRoot));
    };
    try {
        EvalResult r = evaluate_file(path, opt);
        for (const Diagnostic& w : r.warnings) {
            warnings.push_back(test::expectation_text(w, path, kRoot));
            add_notes(w);
        }
        lower_to_csg(r.graph);
    } catch (const SourceError& e) {
        // A run that went on after its first error reports all it found.
        for (const Diagnostic& d : e.reported) {
            (d.severity == Severity::Error ? errors : warnings).push_back(test::expectation_text(d, path, kRoot));
            add_notes(d);
        }
        if (e.reported.empty()) {
            errors.push_back(test::expectation_text(e.diagnostic(), path, kRoot));
            add_notes(e.diagnostic());
        }
    }
    CHECK(errors == want.errors);
    CHECK(echoed == want.echoes);
    CHECK(warnings == want.warnings);
    CHECK(notes == want.notes);
}
