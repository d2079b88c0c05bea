// Adaptive AA's edge prediction (render/edge_crossing.hpp) against closed
// forms: two planes' crease seen by a pinhole and an orthographic camera,
// a cylinder's rim (also from the cylinder's own intervals along the
// plate's line), and no prediction where the planes do not cross between
// the side's ends.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "render/edge_crossing.hpp"
#include "render/primitives/primitives.hpp"

using kerf::render::predicted_crossing;
using kerf::render::TangentPlane;

namespace {

// A side's end rays: a pinhole at `eye` through image points a and b (on
// the plane z = 0), or orthographic rays straight down from them.
struct Side {
    glm::dvec3 o0, d0, o1, d1;
};
Side pinhole(glm::dvec3 eye, glm::dvec3 a, glm::dvec3 b) { return {eye, a - eye, eye, b - eye}; }
Side straight_down(glm::dvec3 a, glm::dvec3 b) { return {a, {0, 0, -1}, b, {0, 0, -1}}; }

}  // namespace

TEST_CASE("edge prediction: the crease of two planes, exact for a pinhole and an orthographic camera", "[render][aa]") {
    // Plane P: z = -2 (x < 0.37 seen), plane Q through the line x = 0.37,
    // z = -2, falling at 35°. Rays from image points (x, 0.2, 0), x from -0.5 to 0.5.
    const double edge = 0.37, fall = glm::radians(35.0);
    const TangentPlane p{{0, 0, -2}, {0, 0, 1}}, q{{edge, 0, -2}, {std::sin(fall), 0, std::cos(fall)}};
    const glm::dvec3 a{-0.5, 0.2, 0}, b{0.5, 0.2, 0};
    // Orthographic: the crossing is where the image x is the edge's.
    const Side o = straight_down(a, b);
    const auto s = predicted_crossing(o.o0, o.d0, o.o1, o.d1, p, q);
    REQUIRE(s);
    CHECK(*s == Approx(edge + 0.5).margin(1e-12));
    // Pinhole at height 3: the ray through image x hits z = -2 at 5/3 x.
    const Side ph = pinhole({0, 0, 3}, a, b);
    const auto t = predicted_crossing(ph.o0, ph.d0, ph.o1, ph.d1, p, q);
    REQUIRE(t);
    CHECK(*t == Approx(edge * 3 / 5 + 0.5).margin(1e-12));
    // Whichever plane is given first.
    const auto u = predicted_crossing(ph.o1, ph.d1, ph.o0, ph.d0, q, p);
    REQUIRE(u);
    CHECK(*u == Approx(1 - *t).margin(1e-12));
}

TEST_CASE("edge prediction: a hole's rim from the wall's tangent plane, to a small share of a side", "[render][aa]") {
    // The plate z = 0 minus a vertical cylinder of radius R about the z
    // axis, seen along parallel rays falling towards -x: the hole's far rim
    // (x < 0) is a crease, the plate meeting the wall seen down the hole.
    // The side's rays land on z = 0 from A (in the hole: the ray meets the
    // wall below the rim) to B (on the plate), across the rim at an angle,
    // so the wall curves between the ray's hit and the rim.
    const glm::dvec3 d = glm::normalize(glm::dvec3(-0.5, 0, -1));
    for (const double R : {4.0, 10.0, 40.0}) {
        const glm::dvec3 A{-R + 0.6, 0.3, 0}, B{-R - 0.4, -0.2, 0};
        const glm::dvec3 o0 = A - 5.0 * d, o1 = B - 5.0 * d;
        // Exact: where the landing point A + s(B - A) meets the circle |(x, y)| = R.
        const glm::dvec2 a(A), e = glm::dvec2(B) - a;
        const double qa = glm::dot(e, e), qb = 2 * glm::dot(a, e), qc = glm::dot(a, a) - R * R;
        const double exact = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
        // The ray at A leaves the cylinder's inside through the far wall.
        const glm::dvec2 o(o0), dd(d);
        const double wa = glm::dot(dd, dd), wb = 2 * glm::dot(o, dd), wc = glm::dot(o, o) - R * R;
        const glm::dvec3 hit = o0 + (-wb + std::sqrt(wb * wb - 4 * wa * wc)) / (2 * wa) * d;
        REQUIRE(hit.z < 0);
        const TangentPlane wall{hit, -glm::normalize(glm::dvec3(hit.x, hit.y, 0))};
        const TangentPlane plate{B, {0, 0, 1}};
        const auto s = predicted_crossing(o0, d, o1, d, wall, plate);
        REQUIRE(s);
        INFO("R " << R << ": predicted " << *s << ", exact " << exact);
        CHECK(std::abs(*s - exact) < 0.25 / R);  // the wall leans off as the rim curves away
        CHECK(std::abs(*s - exact) > 1e-6);      // not exact: a curved surface
    }
}

TEST_CASE("edge prediction: nothing where the planes do not cross between the ends", "[render][aa]") {
    const Side o = straight_down({-0.5, 0, 0}, {0.5, 0, 0});
    // Parallel planes (an occluding step): never equal depths.
    CHECK_FALSE(predicted_crossing(o.o0, o.d0, o.o1, o.d1, {{0, 0, 0}, {0, 0, 1}}, {{0, 0, -1}, {0, 0, 1}}));
    // Crossing beyond the side's end (x = 2).
    const double f = glm::radians(40.0);
    CHECK_FALSE(predicted_crossing(o.o0, o.d0, o.o1, o.d1, {{0, 0, 0}, {0, 0, 1}},
                                   {{2, 0, 0}, {std::sin(f), 0, std::cos(f)}}));
}

TEST_CASE("edge prediction: a hole's near and far rim where the plate's face meets the cylinder, exact", "[render][aa]") {
    // As above, the plate z = 0 minus the cylinder |(x, y)| < R, rays
    // falling towards -x. Across the far rim (x < 0) the second corner
    // sees the wall just below the rim (a crease); across the near rim
    // (x > 0) it sees the far wall deep down the hole (an occluding edge,
    // where the two planes meet nowhere near). Either way the edge is where
    // the plate's face leaves the plate for the cylinder.
    const glm::dvec3 d = glm::normalize(glm::dvec3(-0.5, 0, -1));
    for (const double R : {4.0, 10.0, 40.0})
        for (const double side : {-1.0, 1.0}) {
            const glm::dvec3 A{side * (R + 0.4), 0.3, 0}, B{side * (R - 0.6), -0.2, 0};  // plate, hole
            const glm::dvec2 a(A), e = glm::dvec2(B) - a;
            const double qa = glm::dot(e, e), qb = 2 * glm::dot(a, e), qc = glm::dot(a, a) - R * R;
            const double exact = (-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
            const TangentPlane plate{A, {0, 0, 1}};
            const auto cylinder = [&](const glm::dvec3& p) { return std::hypot(p.x, p.y) - R; };
            const auto s = kerf::render::crossing_on_plane(A - 5.0 * d, d, B - 5.0 * d, d, plate, cylinder);
            REQUIRE(s);
            INFO("R " << R << (side < 0 ? ", far rim" : ", near rim") << ": predicted " << *s << ", exact " << exact);
            CHECK(*s == Approx(exact).margin(1e-4));
        }
    // No sign change (the side stays on the plate), or a mesh's infinite distance: nothing.
    const TangentPlane plate{{0, 0, 0}, {0, 0, 1}};
    const glm::dvec3 down{0, 0, -1};
    const auto far_hole = [](const glm::dvec3& p) { return 100 - std::hypot(p.x - 200, p.y); };
    CHECK_FALSE(kerf::render::crossing_on_plane({0, 0, 1}, down, {1, 0, 1}, down, plate, far_hole));
    const auto mesh = [](const glm::dvec3&) { return std::numeric_limits<double>::infinity(); };
    CHECK_FALSE(kerf::render::crossing_on_plane({0, 0, 1}, down, {1, 0, 1}, down, plate, mesh));
}

namespace {

// The cylinder leaf |(x, y)| < r, -1 < z < 1 (object space = world).
kerf::csg::Leaf hole_leaf(double r) {
    kerf::csg::Leaf l;
    l.kind = kerf::csg::PrimKind::Cylinder;
    l.p[0] = -1, l.p[1] = 1, l.p[2] = r, l.p[3] = r;
    return l;
}

// crossing_on_line() of the plate z = 0 (its plane) against that leaf,
// from csg::intersect_leaf's spans, as adaptive_aa.cpp asks it.
kerf::render::LineCrossing from_spans(const Side& side, const kerf::csg::Leaf& leaf) {
    const TangentPlane plate{{0, 0, 0}, {0, 0, 1}};
    return kerf::render::crossing_on_line(side.o0, side.d0, side.o1, side.d1, plate,
                                          [&](const glm::dvec3& a, const glm::dvec3& b, kerf::csg::Span<double>* out) {
                                              return kerf::csg::intersect_leaf<double>(leaf, a, b - a, out, 0.0, 1.0);
                                          });
}

// How far from the rim the ray at s along the side meets the plate:
// its direction mix(d0, d1, s), as the side's rays run in crossing_on_plane.
double off_rim(const Side& side, double s, double r) {
    const glm::dvec3 o = glm::mix(side.o0, side.o1, s), d = glm::mix(side.d0, side.d1, s);
    const glm::dvec3 p = o - o.z / d.z * d;
    return std::hypot(p.x, p.y) - r;
}

}  // namespace

TEST_CASE("edge prediction: a hole's rim from the cylinder's own intervals, exact for a pinhole and an orthographic "
          "camera",
          "[render][aa]") {
    // The plate z = 0 minus the cylinder of radius 3: the side runs from A
    // on the plate to B over the hole. The pinhole's end rays have
    // different lengths (the plane at depth 0.5 of one, 2 of the other:
    // camera rays are not normalised), so a crossing found a fraction u
    // along the line A→B lies at s = u·t1 / ((1 − u)·t0 + u·t1) along the
    // side, not at u; the orthographic rays lean.
    const double r = 3;
    const kerf::csg::Leaf leaf = hole_leaf(r);
    const glm::dvec3 A{3.4, 0.3, 0}, B{2.5, -0.2, 0}, eye{7, 2, 9};
    const Side sides[2] = {{eye, 2.0 * (A - eye), eye, 0.5 * (B - eye)},
                           {A - 5.0 * glm::dvec3(0.3, 0.1, -1), {0.3, 0.1, -1}, B - 5.0 * glm::dvec3(0.3, 0.1, -1),
                            {0.3, 0.1, -1}}};
    const auto cylinder = [&](const glm::dvec3& p) { return std::hypot(p.x, p.y) - r; };
    for (const Side& side : sides) {
        const kerf::render::LineCrossing c = from_spans(side, leaf);
        REQUIRE(c.applies);
        REQUIRE(c.at);
        const auto falsi = kerf::render::crossing_on_plane(side.o0, side.d0, side.o1, side.d1,
                                                           TangentPlane{{0, 0, 0}, {0, 0, 1}}, cylinder);
        REQUIRE(falsi);
        INFO("from the spans " << *c.at << ", regula falsi " << *falsi);
        // The ray there meets the plate on the rim, to rounding; regula
        // falsi's answer lies within its 1/1,024 of the side.
        CHECK(std::abs(off_rim(side, *c.at, r)) < 1e-12);
        CHECK(std::abs(*c.at - *falsi) < 1.0 / 1024);
        // Backwards (from B to A): the same point.
        const kerf::render::LineCrossing back = from_spans({side.o1, side.d1, side.o0, side.d0}, leaf);
        REQUIRE(back.at);
        CHECK(*back.at == Approx(1 - *c.at).margin(1e-12));
    }
    // Both ends on the plate, beside the hole: no crossing, and said so.
    const kerf::render::LineCrossing none = from_spans({eye, glm::dvec3(4, 1, 0) - eye, eye, glm::dvec3(5, 1, 0) - eye}, leaf);
    CHECK(none.applies);
    CHECK_FALSE(none.at);
    // An end on the rim (within 1/65,536 of the side: whether it lies
    // inside is rounding's to say): left to regula falsi, whose distance
    // at the end says it.
    for (const double off : {0.0, 1e-6, -1e-6})
        CHECK_FALSE(from_spans({eye, glm::dvec3(r + off, 0, 0) - eye, eye, glm::dvec3(r - 1, 0, 0) - eye}, leaf).applies);
    // A half-space's infinite span end: the plane x <= 2.7 (a plane leaf)
    // met by the plate along the same pinhole side, at x = 2.7.
    kerf::csg::Leaf half;
    half.kind = kerf::csg::PrimKind::Plane;
    half.p[0] = 1, half.p[3] = 2.7;
    const kerf::render::LineCrossing wall = from_spans(sides[0], half);
    REQUIRE(wall.applies);
    REQUIRE(wall.at);
    const glm::dvec3 o = sides[0].o0, d = glm::mix(sides[0].d0, sides[0].d1, *wall.at);
    CHECK((o - o.z / d.z * d).x == Approx(2.7).margin(1e-12));
    // Rays of neither one origin nor one direction: the plane's points
    // do not lie on a line.
    CHECK_FALSE(from_spans({eye, A - eye, eye + glm::dvec3(1, 0, 0), B - eye}, leaf).applies);
}
