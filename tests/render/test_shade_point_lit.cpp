// Shader::shade_point_lit, the path of one point light on opaque surfaces
// (render/shading.cpp), against the general one: the same scene with a
// second light whose intensity is 0 (it adds nothing, view_light drops it)
// goes the general way; every ray's colour must be the same bits, and the
// same shadow rays counted. Spheres moved, scaled and turned (the normal's
// short path and the general one), a box minus a sphere (cut faces), a
// checker, an emitter, a fractional and an odd shininess, a mirror (the
// general path in both), and the moved sphere's normal against the
// object normal's formula; lights plain, coloured and dim, with inverse-square
// fall-off, a spot, one casting no shadows.
#include <catch2/catch.hpp>

#include <cstring>
#include <limits>

#include "render/primitives/primitives.hpp"
#include "render/shading.hpp"
#include "tests/render/random_csg.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

csg::Scene scene_with(const csg::Light& light, bool second) {
    Tree tree = op(Op::Union, {});
    tree.kids.push_back(leaf(sphere(0.6, translate(-1, 0, 0), 0)));
    tree.kids.push_back(leaf(sphere(0.5, translate(0.3, 0.4, 0.2) * scale(1, 1.5, 0.8) * rotate_deg(30, {1, 1, 0}), 1)));
    tree.kids.push_back(leaf(sphere(0.4, translate(0.9, -0.6, 0.5), 2)));
    tree.kids.push_back(leaf(sphere(0.3, translate(-0.2, -0.9, 0.9), 3)));
    Tree cut = op(Op::Difference, {});
    cut.kids.push_back(leaf(box({-2, -2, -1.2}, {2, 2, -0.8}, glm::dmat4(1.0), 0)));
    cut.kids.push_back(leaf(sphere(0.7, translate(0.5, 0.2, -0.9), 1)));
    tree.kids.push_back(cut);
    std::vector<csg::Material> mats(4);
    mats[1].pattern = csg::Pattern::Checker;
    mats[1].color2 = {0.1, 0.3, 0.9};
    mats[2].emission = {0.05, 0.02, 0.0};
    mats[2].shininess = 12.5;
    mats[2].specular = 0.6;
    mats[3].shininess = 33;
    mats[3].reflect = 0.4;
    csg::Scene s = make_scene(tree, mats);
    s.lights = {light};
    if (second) {
        csg::Light none = light;
        none.intensity = 0;
        s.lights.push_back(none);
    }
    return s;
}

// A ray from in front of scene_with's solids to a random point among them.
render::TraceRay toward_scene(RandomCsg& g) {
    const glm::dvec3 o = glm::dvec3(g.uni(-1, 1), -6, g.uni(1, 3));
    const glm::dvec3 target(g.uni(-1.8, 1.8), g.uni(-1.5, 1.5), g.uni(-1.1, 1.2));
    return render::TraceRay{o, target - o, 0, kInf};
}

bool same_bits(const glm::dvec3& a, const glm::dvec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("one point light on opaque surfaces: its own shading path gives the general path's bits",
          "[render][shading]") {
    std::vector<csg::Light> lights;
    csg::Light l{false, {-4, -6, 7}, {0, 0, -1}, {1, 1, 1}, 1};
    lights.push_back(l);
    l.color = {0.9, 0.6, 0.3};
    l.intensity = 0.7;
    lights.push_back(l);
    l.inverse_square = true;
    l.intensity = 60;
    lights.push_back(l);
    l.inverse_square = false;
    l.intensity = 1;
    l.spot = true;
    l.direction = glm::normalize(glm::dvec3(4, 6, -7));
    l.spot_angle = 8;
    l.spot_falloff = 6;
    lights.push_back(l);
    l.spot = false;
    l.shadows = false;
    lights.push_back(l);
    RandomCsg g(7);
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const csg::Scene one = scene_with(lights[li], false), two = scene_with(lights[li], true);
        const render::CsgTracer t1(one, false), t2(two, false);
        const render::Shader s1(one, t1, 4), s2(two, t2, 4);
        render::ThreadState ts1, ts2;
        int hits = 0, lit = 0, moved = 0;
        for (int i = 0; i < 600; ++i) {
            const render::TraceRay ray = toward_scene(g);
            std::uint32_t id1 = 0, id2 = 0;
            const glm::dvec3 c1 = s1.radiance(ray, 0, ts1, &id1), c2 = s2.radiance(ray, 0, ts2, &id2);
            INFO("light " << li << " ray " << i << ": " << c1.x << " " << c1.y << " " << c1.z << " against " << c2.x
                          << " " << c2.y << " " << c2.z);
            CHECK(same_bits(c1, c2));
            CHECK(id1 == id2);
            hits += id1 != 0;
            // A moved sphere's normal (the tracer's short path) against the
            // object normal's general formula on the same object point.
            render::TraceHit hit;
            if (t1.intersect(ray, hit, ts1.scratch) && hit.surface.leaf == 0 && !hit.surface.cut) {
                const csg::Leaf& leaf = one.leaves[0];
                const glm::dvec3 p = ray.o + hit.t * ray.d;
                const glm::dvec3 q = p + leaf.object_from_world.offset;
                const glm::dvec3 n_obj = csg::object_normal(leaf, q, hit.surface.part);
                CHECK(same_bits(t1.normal(hit, p), n_obj / glm::length(n_obj)));
                ++moved;
            }
            lit += c1.x > 0.2;
        }
        CHECK(ts1.rays.shadow == ts2.rays.shadow);
        CHECK(hits > 200);
        CHECK(lit > 20);
        CHECK(moved > 20);
    }
}

TEST_CASE("one point light: glass, a light with a radius and ambient occlusion leave the point-lit path as the general one",
          "[render][shading]") {
    // What the point-lit path must not take (Shader::shade's gate and
    // one_point_light_): a transparent surface, a soft light, occlusion of
    // the ambient term. Each scene against its twin with a dark second light
    // (the general path throughout): the same bits.
    for (int variant = 0; variant < 3; ++variant) {
        csg::Light l{false, {-4, -6, 7}, {0, 0, -1}, {1, 1, 1}, 1};
        if (variant == 1) l.radius = 0.5, l.samples = 8;
        csg::Scene one = scene_with(l, false), two = scene_with(l, true);
        for (csg::Scene* s : {&one, &two}) {
            if (variant == 0) s->materials[3].reflect = 0, s->materials[3].transparency = 0.6, s->materials[3].ior = 1.5;
            if (variant == 2) s->ambient_occlusion.samples = 4, s->ambient_occlusion.distance = 1;
        }
        const render::CsgTracer t1(one, false), t2(two, false);
        const render::Shader s1(one, t1, 4), s2(two, t2, 4);
        render::ThreadState ts1, ts2;
        RandomCsg g(11);
        int hits = 0;
        for (int i = 0; i < 400; ++i) {
            const render::TraceRay ray = toward_scene(g);
            std::uint32_t id1 = 0, id2 = 0;
            const glm::dvec3 c1 = s1.radiance(ray, 0, ts1, &id1), c2 = s2.radiance(ray, 0, ts2, &id2);
            INFO("variant " << variant << " ray " << i);
            CHECK(same_bits(c1, c2));
            hits += id1 != 0;
        }
        CHECK(hits > 100);
    }
}
