// Renders the reference models of docs/spec.md §9, built directly as csg::Scene (no
// interpreter), and prints timing and per-ray operation counts. For profiling
// the tracer alone:  render_models MODEL [size] [spp] [threads] [out.png]
// KERF_FLOAT=1 measures the float path.
// MODEL: shell65 | shell16 | checkered | holesN (e.g. holes40; radius 4/N, i.e. 0.1 at N = 40) | grooved
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <string>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

void frame(csg::Scene& s, glm::dvec3 dir, double fov = 40) {
    const csg::Aabb b = s.bounds();
    const glm::dvec3 c = 0.5 * (b.lo + b.hi);
    const double r = 0.5 * glm::length(b.hi - b.lo);
    s.camera.look_at = c;
    s.camera.fov = fov;
    s.camera.position = c + glm::normalize(dir) * (r / std::sin(glm::radians(fov / 2)));
    s.lights = {csg::Light{false, s.camera.position + glm::dvec3(-r, 0, 2 * r), {}, {1, 1, 1}, 0.9},
                csg::Light{false, s.camera.position, {}, {1, 1, 1}, 0.2}};
}

csg::Scene large_shell() {
    const double s = 0.989227963463;
    std::vector<Tree> segs;
    glm::dmat4 m = translate(3, 0, 0);
    for (int k = 0; k < 65; ++k) {
        segs.push_back(op(Op::Difference, {leaf(sphere(1, m)), leaf(sphere(1, m * scale(s, s, s) * translate(0, -.02, 0))),
                                           leaf(sphere(1, m * scale(s, s, s) * translate(0, .02, 0)))}));
        m = scale(0.979, 0.979, 0.979) * rotate_deg(12, {0, 0, 1}) * m;
    }
    csg::Scene sc = make_scene(op(Op::Union, segs));
    frame(sc, {0.3, -1, 1.2});
    return sc;
}

csg::Scene small_shell() {
    std::vector<Tree> segs;
    glm::dmat4 m(1.0);
    for (int k = 0; k < 16; ++k) {
        const glm::dmat4 plane = scale(10, 10, 10) * translate(0, -.5, -.5);
        segs.push_back(op(Op::Difference, {leaf(sphere(1, m * translate(0, -2, 0))),
                                           leaf(sphere(1, m * translate(0, -2, 0) * scale(.95, .95, .95))),
                                           leaf(box({0, 0, 0}, {1, 1, 1}, m * rotate_deg(18, {0, 0, 1}) * plane)),
                                           leaf(box({0, 0, 0}, {1, 1, 1}, m * rotate_deg(162, {0, 0, 1}) * plane))}));
        m = scale(0.93, 0.93, 0.93) * rotate_deg(22.5, {0, 0, 1}) * m;
    }
    csg::Scene sc = make_scene(op(Op::Union, segs));
    frame(sc, {0.4, -1, 0.9});
    return sc;
}

csg::Scene checkered() {
    std::vector<Tree> kids{leaf(box({-1.1, -1.1, -1.1}, {1.1, 1.1, 1.1}))};
    const glm::dmat4 rots[6] = {glm::dmat4(1.0), rotate_deg(90, {1, 0, 0}), rotate_deg(180, {1, 0, 0}),
                                rotate_deg(270, {1, 0, 0}), rotate_deg(90, {0, 1, 0}), rotate_deg(270, {0, 1, 0})};
    for (const glm::dmat4& r : rots)
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j)
                kids.push_back(leaf(box({-.1, -.1, -.1}, {.1, .1, .1}, r * translate(-0.4 * i, -0.4 * j, 0) * translate(.8, .8, 1.1))));
    csg::Scene sc = make_scene(op(Op::Difference, kids));
    frame(sc, {1, -1, 0.8});
    return sc;
}

csg::Scene holes(int n) {
    std::vector<Tree> kids{leaf(box({0, 0, 0}, {10, 10, 1}))};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            kids.push_back(leaf(make_leaf(csg::PrimKind::Cylinder, {0, 3, 4.0 / n, 4.0 / n}, translate((i + 0.5) * 10 / n, (j + 0.5) * 10 / n, -1))));
    csg::Scene sc = make_scene(op(Op::Difference, kids));
    frame(sc, {0.5, -1, 1.5});
    return sc;
}

csg::Scene grooved() {
    const glm::dmat4 t = translate(0, 0, 0.374) * scale(.9, .9, .9);
    const glm::dmat4 flips[2] = {glm::dmat4(1.0), rotate_deg(180, {0, 1, 0})};
    const glm::dmat4 axes[3] = {glm::dmat4(1.0), rotate_deg(90, {0, 1, 0}), rotate_deg(90, {1, 0, 0})};
    std::vector<Tree> kids{leaf(sphere(1))};
    for (const auto& a : axes)
        for (const auto& f : flips) kids.push_back(leaf(make_leaf(csg::PrimKind::Torus, {1, 0.1}, a * f * t)));
    csg::Scene sc = make_scene(op(Op::Difference, kids));
    frame(sc, {1, -1, 0.8});
    return sc;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string model = argc > 1 ? argv[1] : "shell65";
    render::RenderOptions o;
    o.width = o.height = argc > 2 ? std::atoi(argv[2]) : 512;
    o.spp = argc > 3 ? std::atoi(argv[3]) : 1;
    o.threads = argc > 4 ? std::atoi(argv[4]) : 0;
    o.double_precision = std::getenv("KERF_FLOAT") == nullptr;  // KERF_FLOAT=1: the float path
    csg::Scene s;
    if (model == "shell65") s = large_shell();
    else if (model == "shell16") s = small_shell();
    else if (model == "checkered") s = checkered();
    else if (model == "grooved") s = grooved();
    else if (model.rfind("holes", 0) == 0) s = holes(std::atoi(model.c_str() + 5));
    else { std::fprintf(stderr, "unknown model\n"); return 2; }
    render::RenderStats st;
    const std::clock_t cpu0 = std::clock();
    const render::Image im = render::render(s, o, &st);
    const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    const double rays = double(st.rays());
    std::printf("%s %dx%d spp %d: cpu %.3f s, wall %.3f s, %.2f MRay/s, rays %.0f (primary %llu), per ray: union %.2f diff %.2f inter %.2f tests %.2f\n",
                model.c_str(), o.width, o.height, o.spp, cpu, st.seconds, rays / st.seconds * 1e-6, rays,
                (unsigned long long)st.primary_rays, st.union_ops / rays, st.difference_ops / rays,
                st.intersection_ops / rays, st.interval_tests / rays);
    if (argc > 5) render::write_image(im, argv[5]);
}
