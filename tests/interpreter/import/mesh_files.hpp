// Shared by the import tests: the unit cube every encoding stores, the
// evaluation of a script with its first error's text, and the closed-form
// measures of an imported polygon mesh.
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <string>

#include "tests/interpreter/eval_helpers.hpp"
#include "tests/interpreter/temp_tree.hpp"

namespace kerf::test::mesh_files {

// The unit cube [0,1]^3 as 12 triangles, counter-clockwise seen from
// outside — the winding every one of the three formats prescribes.
inline const std::array<glm::dvec3, 8> kCorners = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                             {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
inline const std::array<std::array<int, 4>, 6> kQuads = {{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

inline kerf::EvalResult eval_file(const std::string& path, kerf::EvalOptions opt = {}) {
    opt.echo = [](const std::string&) {};
    return kerf::evaluate_file(path, opt);
}

// "LINE:COL: error: MESSAGE" of the first error (the temp path left out).
inline std::string error_in(const std::string& path, kerf::EvalOptions opt = {}) {
    try {
        eval_file(path, std::move(opt));
    } catch (const kerf::SourceError& e) {
        std::string head = kerf::format_diagnostic_head(e.diagnostic());
        REQUIRE(head.rfind(path + ":", 0) == 0);
        return head.substr(path.size() + 1);
    }
    return "no error";
}

// The message of the error importing `bytes` as `name` (the location left out).
inline std::string err_of(kerf::test::TempTree& t, const std::string& name, const std::string& bytes) {
    t.write(name, bytes);
    const std::string e = error_in(t.write("s.sdl", "import(\"" + name + "\");\n"));
    return e.rfind("1:1: error: ", 0) == 0 ? e.substr(12) : e;
}

// Signed volume (positive for counter-clockwise-outward faces), area and
// bounds of a polygon mesh, by fanning each face.
struct Measures {
    double volume = 0, area = 0;
    glm::dvec3 lo{1e300}, hi{-1e300};
};

inline Measures measure(const kerf::graph::PolygonMesh& m) {
    Measures r;
    for (const auto& f : m.faces)
        for (std::size_t i = 1; i + 1 < f.size(); ++i) {
            const glm::dvec3 a = m.points.at(f[0]), b = m.points.at(f[i]), c = m.points.at(f[i + 1]);
            r.volume += glm::dot(a, glm::cross(b, c)) / 6;
            r.area += glm::length(glm::cross(b - a, c - a)) / 2;
        }
    for (const auto& p : m.points) r.lo = glm::min(r.lo, p), r.hi = glm::max(r.hi, p);
    return r;
}

}  // namespace kerf::test::mesh_files
