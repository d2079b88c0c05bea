// Expectations written in a script's comments, in the style of Crafting
// Interpreters' test suite: `// ECHO: TEXT` is an echo line the run prints
// (all of them, in order), `// error: LINE:COL: MESSAGE` an error (all of them, in
// order: the run goes on after an error in a top-level statement),
// `// warning: LINE:COL: MESSAGE` a warning (all of them, in order; one
// met again at the same place ends in " (N times)"); `// note: LINE:COL:
// MESSAGE` a call-site note (all of them, in order: the warnings' notes,
// then the error's);
// `// limits: fuzz` runs the script under the fuzzer's limits; `// facets:
// exact` or `// facets: openscad` under that --facets mode. A location
// in another file than the script is written FILE:LINE:COL with FILE
// relative to the repository (stdlib/shapes.sdl:11:5). Shared by the golden
// script runner (test_scripts.cpp) and the docs/language.md examples.
#pragma once
#include <sstream>
#include <string>
#include <vector>

#include "grammar/source.hpp"

namespace kerf::test {

// Text after each occurrence of `marker` up to the end of its line.
inline std::vector<std::string> markers(const std::string& text, const std::string& marker) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        auto p = line.find(marker);
        if (p != std::string::npos) out.push_back(line.substr(p + marker.size()));
    }
    return out;
}

struct Expectations {
    std::vector<std::string> echoes;    // with "ECHO: "
    std::vector<std::string> errors;
    std::vector<std::string> warnings;
    std::vector<std::string> notes;
    bool fuzz_limits = false;
    std::string facets = "auto";  // --facets
};

inline Expectations expectations_of(const std::string& text) {
    Expectations e;
    for (const std::string& t : markers(text, "// ECHO: ")) e.echoes.push_back("ECHO: " + t);
    e.errors = markers(text, "// error: ");
    e.warnings = markers(text, "// warning: ");
    e.notes = markers(text, "// note: ");
    for (const std::string& t : markers(text, "// limits: ")) e.fuzz_limits = e.fuzz_limits || t == "fuzz";
    for (const std::string& t : markers(text, "// facets: ")) e.facets = t;
    return e;
}

// A diagnostic as expectations write it: "LINE:COL: MESSAGE" in the script
// itself, "FILE:LINE:COL: MESSAGE" elsewhere (FILE without `root`'s prefix).
inline std::string expectation_text(const Diagnostic& d, const std::string& script, const std::string& root) {
    std::string where;
    if (d.loc.file && d.loc.file->path != script) {
        where = d.loc.file->path;
        if (where.rfind(root, 0) == 0) where = where.substr(root.size());
        where += ':';
    }
    std::string text = where + std::to_string(d.loc.line) + ':' + std::to_string(d.loc.col) + ": " + d.message;
    return d.repeats > 1 ? text + " (" + std::to_string(d.repeats) + " times)" : text;
}

}  // namespace kerf::test
