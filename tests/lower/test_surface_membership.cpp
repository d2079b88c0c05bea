// surface()'s solid point by point: random points classified by the tracer
// (the spans of a ray through the point) against the closed form of
// OpenSCAD's height map — over each cell the four planes through two
// neighbouring corners and the cell's centre at the mean of the four
// corners, down to the base at min(0, lowest − 1) — computed here from the
// numbers of steps.dat (tests/interpreter/modules/surface/).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/lower/script_scene.hpp"
#include "tests/lower/traced_inside.hpp"

namespace {

// steps.dat as written: row i at y = i, column j at x = j.
constexpr double kRows[3][4] = {{1, 2, 3.5, -1}, {0.5, 4, 2, 1}, {3, -2.25, 0, 6}};
constexpr double kBase = -3.25;

// The height at (x, y) inside the grid: the cell's triangle that holds the
// point (u, v in the cell), interpolated linearly between its corners.
double height(double x, double y) {
    const int j = std::clamp(int(std::floor(x)), 0, 2), i = std::clamp(int(std::floor(y)), 0, 1);
    const double u = x - j, v = y - i;
    const double h00 = kRows[i][j], h10 = kRows[i][j + 1], h01 = kRows[i + 1][j], h11 = kRows[i + 1][j + 1];
    const double c = (h00 + h10 + h01 + h11) / 4;
    // Triangle (p, q, centre) with p, q the ends of one cell side; the
    // point's barycentric weights from the side's two end points.
    auto tri = [&](glm::dvec2 p, double hp, glm::dvec2 q, double hq) {
        const glm::dvec2 m(0.5, 0.5), w(u, v);
        const double det = (p.x - m.x) * (q.y - m.y) - (q.x - m.x) * (p.y - m.y);
        const double a = ((w.x - m.x) * (q.y - m.y) - (q.x - m.x) * (w.y - m.y)) / det;
        const double b = ((p.x - m.x) * (w.y - m.y) - (w.x - m.x) * (p.y - m.y)) / det;
        return a * hp + b * hq + (1 - a - b) * c;
    };
    if (v <= u && v <= 1 - u) return tri({0, 0}, h00, {1, 0}, h10);
    if (u >= v && u >= 1 - v) return tri({1, 0}, h10, {1, 1}, h11);
    if (v >= u && v >= 1 - u) return tri({1, 1}, h11, {0, 1}, h01);
    return tri({0, 1}, h01, {0, 0}, h00);
}

bool traced_inside(const kerf::render::CsgTracer& tr, kerf::render::TraceScratch& scratch, const glm::dvec3& p) {
    return kerf::test::traced_inside(tr, scratch, p, glm::normalize(glm::dvec3(0.23, 0.31, 1)));
}

}  // namespace

TEST_CASE("surface()'s solid is OpenSCAD's four triangles per cell over a flat base") {
    auto ev = kerf::test::evaluated("translate([10, -20, 5]) surface(\"steps.dat\");",
                                    std::string(KERF_SOURCE_DIR) + "/tests/interpreter/modules/surface/test.sdl");
    const kerf::csg::Scene scene = kerf::lower_to_csg(ev.graph);
    const kerf::render::CsgTracer tracer(scene, false);
    kerf::render::TraceScratch scratch;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(-0.5, 3.5), uy(-0.5, 2.5), uz(-4, 7);
    int inside = 0, checked = 0, wrong = 0;
    for (int k = 0; k < 4000; ++k) {
        const glm::dvec3 p(ux(rng), uy(rng), uz(rng));
        const bool in_grid = p.x > 0 && p.x < 3 && p.y > 0 && p.y < 2;
        // Away from the walls, the base and the top by 1e-6 (the oracle's margin).
        const double gap = std::min({std::abs(p.x), std::abs(p.x - 3), std::abs(p.y), std::abs(p.y - 2),
                                     std::abs(p.z - kBase),
                                     in_grid ? std::abs(p.z - height(p.x, p.y)) : 1.0});
        if (gap < 1e-6) continue;
        const bool want = in_grid && p.z > kBase && p.z < height(p.x, p.y);
        ++checked;
        inside += want;
        if (want != traced_inside(tracer, scratch, p + glm::dvec3(10, -20, 5))) ++wrong;
    }
    INFO(wrong << " of " << checked << " points disagree, " << inside << " inside");
    CHECK(wrong == 0);
    CHECK(inside > checked / 10);
    CHECK(inside < checked * 9 / 10);
    // Corner heights and centres exactly (points just below and above).
    const glm::dvec3 known[] = {{1, 1, 4}, {0.5, 0.5, 1.875}, {2.5, 1.5, 2.25}, {2.9, 1.9, 5.25}};
    for (const glm::dvec3& k : known) {
        const double x = k.x, y = k.y, h = height(x, y);
        INFO(x << " " << y << " " << h);
        CHECK(h == Approx(k.z));
        CHECK(traced_inside(tracer, scratch, glm::dvec3(x + 10, y - 20, h - 1e-4 + 5)));
        CHECK_FALSE(traced_inside(tracer, scratch, glm::dvec3(x + 10, y - 20, h + 1e-4 + 5)));
    }
}
