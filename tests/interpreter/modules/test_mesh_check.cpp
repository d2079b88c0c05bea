// check_mesh on meshes whose truth is known: a cube wound as OpenSCAD wants
// (clockwise seen from outside), with one face turned, with every face
// reversed, as a triangle soup (STL: three points of its own per triangle),
// open, non-manifold and non-orientable.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "interpreter/modules/mesh_check.hpp"

using namespace kerf;
using kerf::eval::check_mesh;

namespace {

// The unit cube, faces clockwise seen from outside (OpenSCAD's order).
graph::PolygonMesh cube() {
    graph::PolygonMesh m;
    m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.faces = {{0, 1, 2, 3}, {4, 5, 1, 0}, {7, 6, 5, 4}, {5, 6, 2, 1}, {6, 7, 3, 2}, {7, 4, 0, 3}};
    return m;
}

// Six times the signed volume in OpenSCAD's order: -6 for the unit cube.
double volume6(const graph::PolygonMesh& m) {
    double v = 0;
    for (const auto& f : m.faces)
        for (std::size_t k = 1; k + 1 < f.size(); ++k)
            v += glm::dot(m.points[f[0]], glm::cross(m.points[f[k]], m.points[f[k + 1]]));
    return v;
}

void reverse(std::vector<std::uint32_t>& f) { std::reverse(f.begin(), f.end()); }

}  // namespace

TEST_CASE("a well-wound closed mesh is left as it is", "[mesh]") {
    auto m = cube();
    const auto before = m.faces;
    const auto r = check_mesh(m);
    CHECK(r.closed());
    CHECK(r.faces == 6);
    CHECK(r.faces_turned == 0);
    CHECK(m.faces == before);
    CHECK(volume6(m) == Approx(-6));
}

TEST_CASE("one face wound against its neighbours is turned round", "[mesh]") {
    for (std::size_t bad = 0; bad < 6; ++bad) {
        auto m = cube();
        reverse(m.faces[bad]);
        const auto r = check_mesh(m);
        INFO("face " << bad);
        CHECK(r.closed());
        CHECK(r.faces_turned == 1);
        CHECK(m.faces == cube().faces);
    }
}

TEST_CASE("a mesh wound inside out is reversed, also as a triangle soup", "[mesh]") {
    auto m = cube();
    for (auto& f : m.faces) reverse(f);
    auto r = check_mesh(m);
    CHECK(r.faces_turned == 6);
    CHECK(volume6(m) == Approx(-6));

    // The same cube as an STL reader gives it: 12 triangles, 36 points, all
    // reversed (counter-clockwise from outside, as STL writes them).
    graph::PolygonMesh soup;
    for (const auto& f : cube().faces)
        for (std::size_t k = 1; k + 1 < f.size(); ++k)
            for (std::uint32_t i : {f[0], f[k + 1], f[k]}) {
                soup.faces.resize(soup.faces.size() + (soup.points.size() % 3 == 0 ? 1 : 0));
                soup.faces.back().push_back(std::uint32_t(soup.points.size()));
                soup.points.push_back(cube().points[i]);
            }
    REQUIRE(soup.faces.size() == 12);
    REQUIRE(volume6(soup) == Approx(6));
    r = check_mesh(soup);
    CHECK(r.closed());
    CHECK(r.faces_turned == 12);
    CHECK(volume6(soup) == Approx(-6));
}

TEST_CASE("open, non-manifold and non-orientable meshes are reported", "[mesh]") {
    auto open = cube();
    open.faces.pop_back();
    auto r = check_mesh(open);
    CHECK(r.open_edges == 4);
    CHECK_FALSE(r.closed());
    CHECK(r.faces_turned == 0);  // an open part keeps the orientation its faces agree on

    auto fin = cube();  // a seventh face through the edge 0-1
    fin.points.push_back({0.5, -1, 0});
    fin.faces.push_back({0, 1, 8});
    r = check_mesh(fin);
    CHECK(r.nonmanifold_edges == 1);
    CHECK_FALSE(r.closed());

    // A Möbius band of 4 quads: going round flips the orientation.
    graph::PolygonMesh band;
    for (int k = 0; k < 4; ++k) {
        const double a = k * 3.14159265358979 / 2;
        band.points.push_back({std::cos(a), std::sin(a), 0.3});
        band.points.push_back({std::cos(a), std::sin(a), -0.3});
    }
    band.faces = {{0, 1, 3, 2}, {2, 3, 5, 4}, {4, 5, 7, 6}, {6, 7, 0, 1}};  // the last joins twisted
    r = check_mesh(band);
    CHECK(r.nonorientable);
    CHECK_FALSE(r.closed());
}

TEST_CASE("a closed part is turned outward even beside an open one", "[mesh]") {
    auto m = cube();
    for (auto& f : m.faces) reverse(f);  // inside out...
    const std::uint32_t base = std::uint32_t(m.points.size());
    m.points.push_back({5, 0, 0});
    m.points.push_back({6, 0, 0});
    m.points.push_back({5, 1, 0});
    m.faces.push_back({base, base + 1, base + 2});  // ... beside a lone triangle
    const auto r = check_mesh(m);
    CHECK(r.open_edges == 3);
    CHECK(r.faces_turned == 6);
}
