// Materials per leaf and the docs/spec.md §6 scene defaults.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tests/lower/graph_builder.hpp"
#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/render.hpp"

using namespace kerf;
using kerf::test::GraphBuilder;

TEST_CASE("the innermost colour/material scope resolves to each leaf's material") {
    GraphBuilder b;
    csg::Material glass;
    glass.color = {0.1, 0.2, 0.9};
    glass.interior = {0.9, 0.1, 0.1};
    glass.reflect = 0.5;
    const auto unused = b.material(csg::Material{});
    (void)unused;
    const auto glass_index = b.material(glass);
    // material(glass) { sphere; color(green) cube; } plus a bare cylinder
    const auto scoped = b.appearance(glass_index, b.uni({b.sphere(1), b.translate({3, 0, 0}, b.color({0, 1, 0}, b.cube(1)))}));
    const csg::Scene s = lower_to_csg(b.finish({scoped, b.translate({0, 5, 0}, b.cylinder(0, 1, 1, 1))}));
    REQUIRE(s.leaves.size() == 3);
    CHECK(s.materials.size() == 3);  // default + the two used; the unused one is not set up
    const csg::Material& def = s.materials[0];
    CHECK(def.color == glm::dvec3(0.8, 0.8, 0.8));
    const csg::Material& m0 = s.materials[s.leaves[0].material];
    CHECK(m0.color == glass.color);
    CHECK(m0.interior == glass.interior);
    CHECK(m0.reflect == 0.5);
    CHECK(s.materials[s.leaves[1].material].color == glm::dvec3(0, 1, 0));
    CHECK(s.leaves[2].material == 0);
}

TEST_CASE("leaves point back at their statements") {
    GraphBuilder b;
    b.next_line = 12;
    const auto a = b.sphere(1);  // line 12
    const auto c = b.translate({3, 0, 0}, b.sphere(1));  // sphere line 13
    const csg::Scene s = lower_to_csg(b.finish({a, c}));
    REQUIRE(s.leaves.size() == 2);
    REQUIRE(s.files.size() == 1);
    CHECK(s.files[0] == "test.sdl");
    CHECK(s.sources[s.leaves[0].source].line == 12);
    CHECK(s.sources[s.leaves[1].source].line == 13);
    CHECK(s.sources[s.leaves[1].source].col == 1);
}

namespace {

// docs/spec.md §6 pinhole model, written independently of the lowering code:
// returns pixel coordinates of a world point for a W×H image.
glm::dvec2 project(const csg::Camera& c, const glm::dvec3& p, double W, double H) {
    const glm::dvec3 f = glm::normalize(c.look_at - c.position);
    const glm::dvec3 r = glm::normalize(glm::cross(f, c.up));
    const glm::dvec3 u = glm::cross(r, f);
    const glm::dvec3 d = p - c.position;
    const double depth = glm::dot(d, f);
    const double half_h = std::tan(glm::radians(c.fov) / 2);
    const double x = glm::dot(d, r) / depth / (half_h * W / H);  // -1..1 across
    const double y = glm::dot(d, u) / depth / half_h;
    return {(x + 1) / 2 * W, (1 - y) / 2 * H};
}

}  // namespace

// The plain look (--look plain); the studio look's defaults: test_studio.cpp.
TEST_CASE("plain default camera: looks at the box centre from [1,-1,0.8] and frames the whole box") {
    GraphBuilder b;
    const auto top = b.uni({b.translate({2, 3, 4}, b.box({-1, -2, -0.5}, {3, 1, 0.5})), b.translate({-4, 0, 1}, b.sphere(0.5))});
    const csg::Scene s = lower_to_csg(b.finish({top}), {Look::Plain});
    const csg::Aabb box = s.bounds();
    const glm::dvec3 centre = 0.5 * (box.lo + box.hi);
    CHECK(glm::length(s.camera.look_at - centre) == Approx(0).margin(1e-12));
    const glm::dvec3 dir = glm::normalize(s.camera.position - s.camera.look_at);
    const glm::dvec3 want = glm::normalize(glm::dvec3(1, -1, 0.8));
    CHECK(glm::dot(dir, want) == Approx(1));
    CHECK(s.camera.fov == 40);
    CHECK(!s.camera.orthographic);
    for (auto [W, H] : {std::pair{800.0, 600.0}, std::pair{600.0, 600.0}, std::pair{1920.0, 1080.0}}) {
        bool touches_half = false;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 corner((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y, (k & 4) ? box.hi.z : box.lo.z);
            const glm::dvec2 px = project(s.camera, corner, W, H);
            CHECK(px.x >= 0);
            CHECK(px.x <= W);
            CHECK(px.y >= 0);
            CHECK(px.y <= H);
            touches_half = touches_half || std::abs(px.y - H / 2) > 0.25 * H;
        }
        CHECK(touches_half);  // framed, not a speck in the middle
    }
}

TEST_CASE("plain default lights: a key light above-left of the camera and a weak headlight") {
    GraphBuilder b;
    const csg::Scene s = lower_to_csg(b.finish({b.sphere(1)}), {Look::Plain});
    REQUIRE(s.lights.size() == 2);
    const csg::Camera& c = s.camera;
    const glm::dvec3 f = glm::normalize(c.look_at - c.position);
    const glm::dvec3 r = glm::normalize(glm::cross(f, c.up));
    const glm::dvec3 u = glm::cross(r, f);
    const csg::Light& key = s.lights[0];
    CHECK(!key.directional);
    CHECK(glm::dot(key.position - c.position, u) > 0);
    CHECK(glm::dot(key.position - c.position, r) < 0);
    const csg::Light& head = s.lights[1];
    CHECK(glm::length(head.position - c.position) == Approx(0).margin(1e-12));
    CHECK(head.intensity < key.intensity);
    CHECK(s.background == glm::dvec3(0.2, 0.2, 0.2));
}

TEST_CASE("scene statements override the defaults") {
    GraphBuilder b;
    csg::Camera cam;
    cam.position = {0, -10, 0};
    cam.look_at = {0, 0, 0};
    cam.orthographic = true;
    cam.height = 3;
    b.g.camera = cam;
    csg::Light sun;
    sun.directional = true;
    sun.direction = {0, 0, -1};
    sun.intensity = 0.7;
    b.g.lights = {sun};
    b.g.background = glm::dvec3(1, 1, 1);
    const csg::Scene s = lower_to_csg(b.finish({b.sphere(1)}));
    CHECK(s.camera.position == glm::dvec3(0, -10, 0));
    CHECK(s.camera.orthographic);
    CHECK(s.camera.height == 3);
    REQUIRE(s.lights.size() == 1);
    CHECK(s.lights[0].directional);
    CHECK(s.lights[0].intensity == 0.7);
    CHECK(s.background == glm::dvec3(1, 1, 1));
}

TEST_CASE("the default camera frames a solid the same way at every size in the renderable range") {
    // Rendered through lowering and the tracer: the silhouette of a sphere
    // (and of a torus, whose quartic scales with the fourth power) must be
    // the same pixel mask at 1e-30 and at 1e29 as at 1. It used to be empty
    // below ~2e-9 (the radius was replaced by 1) and, past 1e38, a camera at
    // infinity with exit 0.
    auto mask = [](const std::string& text) {
        auto f = std::make_shared<SourceFile>();
        f->path = "test.sdl";
        f->text = text;
        const csg::Scene s = lower_to_csg(evaluate_source(f).graph);
        render::RenderOptions o;
        o.width = 32, o.height = 24, o.threads = 1, o.aov = render::Aov::Depth;
        const render::Image img = render::render(s, o);
        std::vector<bool> m;
        for (float d : img.pixels) m.push_back(std::isfinite(d));
        return m;
    };
    for (const std::string solid : {"sphere(S);", "rotate([60, 0, 30]) torus(S, S / 4);"}) {
        auto with = [&](const std::string& size) {
            std::string t = solid;
            for (std::size_t p; (p = t.find('S')) != std::string::npos;) t.replace(p, 1, size);
            return mask(t);
        };
        const std::vector<bool> unit = with("1");
        const auto covered = std::count(unit.begin(), unit.end(), true);
        CHECK(covered > 60);  // framed: a real part of the 768 pixels
        for (const std::string size : {"1e-30", "1e-12", "2e-9", "1e12", "1e29"}) {
            INFO(solid << " at size " << size);
            CHECK(with(size) == unit);
        }
    }
}
