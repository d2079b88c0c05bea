// Shading far from the origin (docs/accuracy.md "Far from the origin"):
// lights, shadows and cuts of a scene do not change when the whole scene,
// camera and lights included, is moved by 1e4, 1e6 or 1e8. The shadow
// offset used to be 100 times a tolerance of 1e-9 of the largest
// coordinate: at 1e8 shadow rays started 10 units off the surface and a
// lit ball was drawn in shadow.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/render.hpp"
#include "tests/render/random_csg.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

csg::Material flat(glm::dvec3 c) {
    csg::Material m;
    m.color = m.interior = c;
    m.specular = 0;
    m.diffuse = 1;
    return m;
}

const glm::dvec3 kSkew = glm::normalize(glm::dvec3(1, -0.6, 0.3));

}  // namespace

TEST_CASE("lit ground and the shadow of a ball have their closed-form values at any offset", "[render][shading][far]") {
    for (const double far : {0.0, 1e4, 1e6, 1e8}) {
        const glm::dvec3 at = far * kSkew;
        // Ground z <= at.z, red ball above it, distant light at 45°: the
        // shadow's centre is 3 units to +x of the ball (as in test_shading).
        const Tree t = RandomCsg::moved(op(Op::Union, {leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0}, glm::dmat4(1.0), 0)),
                                                       leaf(sphere(1, translate(0, 0, 3), 1))}),
                                        at);
        csg::Scene s = make_scene(t, {flat({0.5, 0.5, 0.5}), flat({1, 0, 0})});
        s.camera.position = at + glm::dvec3(0, -0.001, 10);
        s.camera.look_at = at;
        s.camera.up = {0, 1, 0};
        s.camera.orthographic = true;
        s.camera.height = 8;
        s.lights = {csg::Light{true, {}, {1, 0, -1}, {1, 1, 1}, 0.8}};
        render::RenderOptions o;
        o.width = o.height = 41;
        const render::Image im = render::render(s, o);
        INFO("offset " << far);
        CHECK(im.at(20, 20, 0) == Approx(0.1 + 0.8 * std::sqrt(0.5)).epsilon(2e-2));  // top of the ball, lit
        CHECK(im.at(35, 20, 0) == Approx(0.1 * 0.5).epsilon(1e-5));                   // ground in its shadow
        CHECK(im.at(5, 20, 0) == Approx(0.1 * 0.5 + 0.8 * 0.5 * std::sqrt(0.5)).epsilon(1e-5));  // ground, lit
    }
}

// Random CSG scenes with a point light: the picture moved far away equals
// the picture at the origin (colour within 1 %, in all but silhouette and
// shadow-edge pixels, where the moved rays' last bits may tip a sample).
TEST_CASE("random CSG scenes shade the same far from the origin", "[render][shading][far]") {
    int scenes = 0;
    for (std::uint64_t seed = 1; scenes < 8; ++seed) {
        RandomCsg gen(seed);
        const Tree tree = gen.tree(0, 1 + int(seed % 5));
        const glm::dvec3 eye = 7.0 * glm::normalize(glm::dvec3(gen.uni(-1, 1), gen.uni(-1, 1), gen.uni(-1, 1)) + glm::dvec3(1e-3));
        render::Image reference;
        for (const double far : {0.0, 1e4, 1e6, 1e8}) {
            const glm::dvec3 at = far * kSkew;
            csg::Scene s = make_scene(RandomCsg::moved(tree, at), {flat({0.8, 0.2, 0.2}), flat({0.2, 0.8, 0.2}), flat({0.2, 0.2, 0.8})});
            s.camera.position = at + eye;
            s.camera.look_at = at;
            s.camera.height = 5;
            s.camera.fov = 35;
            s.lights = {csg::Light{false, at + glm::dvec3(4, -5, 8), {}, {1, 1, 1}, 1.0}};
            render::RenderOptions o;
            o.width = 48;
            o.height = 36;
            const render::Image im = render::render(s, o);
            if (far == 0) {
                reference = im;
                continue;
            }
            int differ = 0;
            for (std::size_t i = 0; i < im.pixels.size(); i += 3) {
                bool d = false;
                for (int c = 0; c < 3; ++c) d = d || std::abs(im.pixels[i + c] - reference.pixels[i + c]) > 0.01f;
                differ += d ? 1 : 0;
            }
            INFO("seed " << seed << " offset " << far << ": " << differ << " of " << im.pixels.size() / 3
                         << " pixels differ");
            CHECK(differ * 50 <= int(im.pixels.size() / 3));
        }
        ++scenes;
    }
}
