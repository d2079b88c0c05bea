// Concave polygon faces (an imported OFF's or a polyhedron's) are cut into
// triangles that cover exactly the face: random points classified by the
// tracer (the spans of an oblique ray through the point) against the closed
// form — inside the prism 0 < z < 1 over a comb-shaped section, by the
// even-odd rule. A fan around corner 0 folds over the comb's notches and
// adds crossings outside the face there, which this catches.
#include <catch2/catch.hpp>

#include <random>

#include "tests/interpreter/temp_tree.hpp"
#include "tests/lower/script_scene.hpp"
#include "tests/lower/traced_inside.hpp"

namespace {

// A comb with three teeth, counter-clockwise seen from +z; corner 0 sees
// little of it (a fan from there crosses the notches).
const std::vector<glm::dvec2> kComb = {{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1},
                                       {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};

bool in_comb(double x, double y) {
    bool odd = false;
    for (std::size_t i = 0, j = kComb.size() - 1; i < kComb.size(); j = i++) {
        const glm::dvec2 a = kComb[i], b = kComb[j];
        if ((a.y > y) != (b.y > y) && x < a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y)) odd = !odd;
    }
    return odd;
}

// The comb prism as OFF text: bottom and top as one 12-corner face each,
// counter-clockwise seen from outside; the walls as quads.
std::string comb_off() {
    const std::size_t n = kComb.size();
    std::string s = "OFF\n# a comb prism\n" + std::to_string(2 * n) + " " + std::to_string(n + 2) + " 0\n";
    for (int z = 0; z < 2; ++z)
        for (const glm::dvec2& p : kComb) s += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(z) + "\n";
    s += std::to_string(n);
    for (std::size_t i = n; i-- > 0;) s += " " + std::to_string(i);
    s += "\n" + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i) s += " " + std::to_string(n + i);
    s += "\n";
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        s += "4 " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(n + j) + " " +
             std::to_string(n + i) + "\n";
    }
    return s;
}


}  // namespace

TEST_CASE("an OFF prism with concave 12-corner faces is the comb point by point", "[import][mesh]") {
    kerf::test::TempTree t;
    t.write("comb.off", comb_off());
    const auto ev = kerf::test::evaluated("import(\"comb.off\");", t.path("test.sdl"));
    const kerf::csg::Scene scene = kerf::lower_to_csg(ev.graph);
    REQUIRE(scene.meshes.size() == 1);
    CHECK(scene.meshes[0].triangles.size() == 3 * (2 * 10 + 2 * 12));  // n - 2 per cap, 2 per wall
    const kerf::render::CsgTracer tracer(scene, false);
    kerf::render::TraceScratch scratch;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> x(-0.5, 5.5), y(-0.5, 3.5), z(-0.5, 1.5);
    // Rays nearly along z cross the caps, where a fan would fold; others the walls.
    const glm::dvec3 dirs[] = {glm::normalize(glm::dvec3(0.03, 0.02, 1)), glm::normalize(glm::dvec3(0.9, 0.3, 0.2)),
                               glm::normalize(glm::dvec3(-0.2, 1, 0.1))};
    int inside = 0, wrong = 0;
    for (int i = 0; i < 3000; ++i) {
        const glm::dvec3 p(x(rng), y(rng), z(rng));
        const bool want = p.z > 0 && p.z < 1 && in_comb(p.x, p.y);
        inside += want;
        for (const glm::dvec3& d : dirs) {
            INFO("point " << p.x << " " << p.y << " " << p.z << ", ray " << d.x << " " << d.y << " " << d.z);
            const bool got = kerf::test::traced_inside(tracer, scratch, p, d);
            wrong += got != want;
            CHECK(got == want);
        }
    }
    CHECK(inside > 600);  // the comb is 11 of the 48 sampled
    CHECK(wrong == 0);
}

TEST_CASE("a polyhedron's concave faces are cut into ears, a convex face still fanned", "[mesh]") {
    // The same comb as a polyhedron (OpenSCAD's clockwise order): every
    // triangle of a cap lies inside the comb (its centroid is in the face).
    std::string pts, faces = "[[";
    for (int z = 0; z < 2; ++z)
        for (const glm::dvec2& p : kComb) pts += "[" + std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(z) + "],";
    pts.pop_back();
    const std::size_t n = kComb.size();
    for (std::size_t i = 0; i < n; ++i) faces += std::to_string(i) + (i + 1 < n ? "," : "],[");
    for (std::size_t i = n; i-- > 0;) faces += std::to_string(n + i) + (i > 0 ? "," : "]");
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        faces += ",[" + std::to_string(i) + "," + std::to_string(n + i) + "," + std::to_string(n + j) + "," +
                 std::to_string(j) + "]";
    }
    faces += "]";
    const kerf::csg::Scene scene = kerf::test::lowered("polyhedron(points = [" + pts + "], faces = " + faces + ");");
    REQUIRE(scene.meshes.size() == 1);
    const auto& m = scene.meshes[0];
    std::size_t caps = 0;
    for (std::size_t k = 0; k < m.triangles.size(); k += 3) {
        const glm::dvec3 a = m.points[m.triangles[k]], b = m.points[m.triangles[k + 1]], c = m.points[m.triangles[k + 2]];
        if (a.z != b.z || b.z != c.z) continue;
        ++caps;
        const glm::dvec3 g = (a + b + c) / 3.0;
        INFO("triangle centroid " << g.x << " " << g.y);
        CHECK(in_comb(g.x, g.y));
        // Outward: down on the bottom cap, up on the top.
        CHECK((glm::cross(b - a, c - a).z > 0) == (a.z > 0.5));
    }
    CHECK(caps == 2 * (n - 2));
}
