// hull() lowering speed (issue 14: 10,000 points in < 50 ms): a Hull node
// over one polyhedron of N points, lowered several times; prints the CPU
// time (user + sys, immune to other processes) median of the whole
// lower_to_csg and of convex_hull alone, per scene:
//   sphere  N points on the unit sphere (every point a corner: the worst case)
//   ball    N points uniform in the unit ball (few corners, many inside)
//   bench_hull [points=10000] [runs=21]
// Before/after comparisons run two builds of this file alternately
// (docs/accuracy.md, "Hulls", gives the commands).
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <vector>

#include "lower/convex_hull.hpp"
#include "lower/lower.hpp"

using namespace kerf;

namespace {

double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::vector<glm::dvec3> scene_points(bool sphere, int count) {
    std::mt19937 rng(3);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<glm::dvec3> p;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
        p.push_back(sphere ? d : std::cbrt(u(rng)) * d);
    }
    return p;
}

// hull() { polyhedron(points, faces of their hull); }
graph::SceneGraph hull_scene(const std::vector<glm::dvec3>& pts) {
    graph::SceneGraph g;
    const SourceLoc loc{std::make_shared<SourceFile>(SourceFile{"bench.sdl", ""}), 1, 1};
    graph::PolygonMesh m;
    m.points = pts;
    for (const auto& f : convex_hull(pts).faces) m.faces.emplace_back(f.rbegin(), f.rend());
    g.meshes.push_back(std::move(m));
    graph::Node mesh;
    mesh.kind = graph::NodeKind::Primitive;
    mesh.prim = csg::PrimKind::Mesh;
    mesh.loc = loc;
    g.nodes.push_back(mesh);
    graph::Node hull;
    hull.kind = graph::NodeKind::Hull;
    hull.p[0] = 1e-4;  // the default curve tolerance (unused: no curves)
    hull.first_child = 0;
    hull.child_count = 1;
    hull.loc = loc;
    g.child_refs.push_back(0);
    g.nodes.push_back(hull);
    graph::Node root;
    root.first_child = 1;
    root.child_count = 1;
    g.child_refs.push_back(1);
    g.nodes.push_back(root);
    g.root = 2;
    return g;
}

template <typename F>
double median_cpu_ms(int runs, F&& f) {
    std::vector<double> t;
    for (int r = 0; r < runs; ++r) {
        const double c0 = cpu_seconds();
        f();
        t.push_back(1e3 * (cpu_seconds() - c0));
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const int count = argc > 1 ? std::atoi(argv[1]) : 10000;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 21;
    for (bool sphere : {true, false}) {
        const std::vector<glm::dvec3> pts = scene_points(sphere, count);
        const graph::SceneGraph g = hull_scene(pts);
        std::size_t leaves = 0, corners = 0;
        const double lower_ms = median_cpu_ms(runs, [&] { leaves = lower_to_csg(g).leaves.size(); });
        const double qhull_ms = median_cpu_ms(runs, [&] { corners = convex_hull(pts).points.size(); });
        std::printf("%-6s %d points, %zu corners, %zu leaves: lower_to_csg median %.2f ms CPU, convex_hull %.2f ms "
                    "(%d runs)\n",
                    sphere ? "sphere" : "ball", count, corners, leaves, lower_ms, qhull_ms, runs);
    }
    return 0;
}
