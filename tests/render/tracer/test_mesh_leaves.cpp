// Mesh leaves (Embree triangle geometry, all crossings paired into spans)
// against the analytic box they tessellate, alone and inside CSG.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

// The box [lo, hi] as 12 triangles, wound counter-clockwise seen from outside.
csg::Mesh box_mesh(glm::dvec3 lo, glm::dvec3 hi) {
    csg::Mesh m;
    for (int c = 0; c < 8; ++c) m.points.push_back({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z});
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    const glm::dvec3 centre = 0.5 * (lo + hi);
    for (const auto& q : quads)
        for (int t : {0, 1}) {
            std::uint32_t a = std::uint32_t(q[0]), b = std::uint32_t(q[t + 1]), c = std::uint32_t(q[t + 2]);
            const glm::dvec3 n = glm::cross(m.points[b] - m.points[a], m.points[c] - m.points[a]);
            if (glm::dot(n, m.points[a] - centre) < 0) std::swap(b, c);
            m.triangles.insert(m.triangles.end(), {a, b, c});
        }
    return m;
}

csg::Leaf mesh_leaf(std::uint32_t mesh, const csg::Mesh& m, const glm::dmat4& world) {
    csg::Leaf l = make_leaf(csg::PrimKind::Mesh, {}, world);
    l.mesh = mesh;
    l.bounds = csg::Aabb{};
    for (const glm::dvec3& p : m.points) l.bounds.extend(l.world_from_object.point(p));
    return l;
}

int compare(const csg::Scene& a, const csg::Scene& b, int& hits) {
    render::RenderOptions o;
    o.width = 48;
    o.height = 36;
    o.aov = render::Aov::Depth;
    const render::Image da = render::render(a, o), db = render::render(b, o);
    o.aov = render::Aov::Normal;
    const render::Image na = render::render(a, o), nb = render::render(b, o);
    int bad = 0;
    hits = 0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const float u = da.at(x, y, 0), v = db.at(x, y, 0);
            hits += std::isfinite(v);
            bool same = std::isfinite(u) == std::isfinite(v) && (!std::isfinite(u) || std::abs(u - v) < 1e-4f * v);
            for (int c = 0; c < 3 && same && std::isfinite(v); ++c) same = std::abs(na.at(x, y, c) - nb.at(x, y, c)) < 1e-4f;
            bad += !same;
        }
    return bad;
}

const glm::dmat4 kPose = translate(0.2, -0.1, 0.3) * rotate_deg(35, glm::normalize(glm::dvec3(1, -2, 0.5))) * scale(1.2, 0.8, 1);

}  // namespace

TEST_CASE("a box mesh renders like the analytic box", "[render][mesh]") {
    const csg::Mesh m = box_mesh({-1, -1, -1}, {1, 1, 1});
    csg::Scene meshed = make_scene(leaf(mesh_leaf(0, m, kPose)));
    meshed.meshes = {m};
    const csg::Scene analytic = make_scene(leaf(box({-1, -1, -1}, {1, 1, 1}, kPose)));
    int hits = 0;
    CHECK(compare(meshed, analytic, hits) == 0);
    CHECK(hits > 200);
}

TEST_CASE("mesh leaves combine in CSG like analytic ones (cut faces, inside-out spans)", "[render][mesh]") {
    const csg::Mesh m = box_mesh({-1, -1, -1}, {1, 1, 1});
    const csg::Leaf ball = sphere(1.1, translate(0.5, -0.6, 0.4));
    csg::Scene meshed = make_scene(op(Op::Difference, {leaf(mesh_leaf(0, m, kPose)), leaf(ball)}));
    meshed.meshes = {m};
    const csg::Scene analytic = make_scene(op(Op::Difference, {leaf(box({-1, -1, -1}, {1, 1, 1}, kPose)), leaf(ball)}));
    int hits = 0;
    CHECK(compare(meshed, analytic, hits) == 0);
    CHECK(hits > 200);
    // The mesh as subtrahend: its leaving crossings become the visible faces.
    csg::Scene meshed2 = make_scene(op(Op::Difference, {leaf(sphere(1.3)), leaf(mesh_leaf(0, m, translate(0.6, -0.7, 0.5) * scale(0.7, 0.7, 0.7)))}));
    meshed2.meshes = {m};
    const csg::Scene analytic2 = make_scene(op(Op::Difference, {leaf(sphere(1.3)), leaf(box({-1, -1, -1}, {1, 1, 1}, translate(0.6, -0.7, 0.5) * scale(0.7, 0.7, 0.7)))}));
    CHECK(compare(meshed2, analytic2, hits) == 0);
    CHECK(hits > 200);
}

TEST_CASE("an empty mesh is an empty solid", "[render][mesh]") {
    csg::Mesh empty;
    csg::Leaf l = make_leaf(csg::PrimKind::Mesh, {});
    l.mesh = 0;
    l.bounds = {glm::dvec3(-1), glm::dvec3(1)};
    csg::Scene s = make_scene(op(Op::Union, {leaf(l), leaf(sphere(0.5, translate(3, 0, 0)))}));
    s.meshes = {empty};
    render::RenderOptions o;
    o.width = 16;
    o.height = 12;
    o.aov = render::Aov::Depth;
    const render::Image im = render::render(s, o);
    int hits = 0;
    for (float v : im.pixels) hits += std::isfinite(v) ? 1 : 0;
    CHECK(hits > 0);  // the sphere
    CHECK(!std::isfinite(im.at(8, 6, 0)));  // nothing where the mesh's box is
}

TEST_CASE("a non-solid mesh is a thin shell seen from both sides", "[render][mesh]") {
    // One triangle in the plane y = 0, normal +y (facing away from the camera).
    csg::Mesh tri;
    tri.points = {{-2, 0, -2}, {0, 0, 2}, {2, 0, -2}};
    tri.triangles = {0, 1, 2};
    tri.solid = false;
    REQUIRE(glm::cross(tri.points[1] - tri.points[0], tri.points[2] - tri.points[0]).y > 0);
    for (double side : {-1.0, 1.0}) {
        csg::Scene s = make_scene(leaf(mesh_leaf(0, tri, glm::dmat4(1.0))));
        s.meshes = {tri};
        s.camera.position = {0, 5 * side, 0};
        render::RenderOptions o;
        o.width = 9;
        o.height = 9;
        o.aov = render::Aov::Depth;
        const render::Image depth = render::render(s, o);
        CHECK(depth.at(4, 4, 0) == Approx(5.0).epsilon(1e-6));
        o.aov = render::Aov::Normal;
        const render::Image normal = render::render(s, o);
        CHECK(normal.at(4, 4, 1) == Approx(side));  // faces the camera
        CHECK(std::isinf(depth.at(0, 0, 0)));       // outside the triangle
    }
}
