// Measuring a .scad scene two ways for the import tests: `kerf measure`
// through the real binary, and the volume of OpenSCAD's own STL export of
// the same scene (the independent oracle, when openscad is installed).
#pragma once
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/cli/run_kerf.hpp"

struct Measured {
    double volume = NAN, error = NAN;
    std::string out, err;
    int status = -1;
};

// `kerf measure` of `scad` (which imports the drawings beside it) written
// as the scene file `name` (its extension picks the dialect), with
// `options` added to the command line.
inline Measured measure_file(const std::filesystem::path& dir, const std::string& scad, const std::string& name,
                             const std::string& options = "") {
    const std::string scene = write_file(dir / name, scad + "\n");
    auto r = run_kerf("measure '" + scene + "' --resolution 256" + options, dir);
    Measured m;
    m.status = r.status, m.out = r.out, m.err = r.err;
    if (const std::size_t at = r.out.find("volume: "); at != std::string::npos) {
        char* end = nullptr;
        m.volume = std::strtod(r.out.c_str() + at + 8, &end);
        const std::size_t pm = r.out.find("\xc2\xb1", at);
        if (pm != std::string::npos) m.error = std::strtod(r.out.c_str() + pm + 2, nullptr);
    }
    return m;
}

// `kerf measure` of `scad` as a `.scad` file, with `options` added.
inline Measured measure(const std::filesystem::path& dir, const std::string& scad, const std::string& options = "") {
    return measure_file(dir, scad, "scene.scad", options);
}

// The volume of OpenSCAD's ASCII STL export of `scad`, or NaN without openscad.
inline double openscad_volume(const std::filesystem::path& dir, const std::string& scad) {
    if (std::system("command -v openscad >/dev/null 2>&1") != 0) return NAN;
    const std::string file = write_file(dir / "reference.scad", scad + "\n");
    const std::string stl = (dir / "reference.stl").string();
    if (std::system(("cd '" + dir.string() + "' && openscad -o '" + stl + "' '" + file + "' >/dev/null 2>&1").c_str()))
        return NAN;
    std::ifstream in(stl);
    std::string word;
    double v = 0, p[3][3];
    int k = 0;
    while (in >> word)
        if (word == "vertex") {
            in >> p[k][0] >> p[k][1] >> p[k][2];
            if (++k == 3) {
                v += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                      p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) / 6;
                k = 0;
            }
        }
    return v;
}

inline void check_volume(const Measured& m, double want, double rel = 1e-3) {
    INFO(m.out << m.err);
    REQUIRE(m.status == 0);
    REQUIRE(std::isfinite(m.error));
    CHECK(std::abs(m.volume - want) <= m.error + rel * want);
}
