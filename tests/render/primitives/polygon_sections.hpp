// Polygon sets for the prism and lathe tests: paths added edge by edge
// (with their vertices kept, for rays aimed through them), random stars,
// and the distance from a point to an edge, which the tests' surface bands
// are measured with.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::test {

struct Section {
    csg::Polygon2 poly;
    std::vector<glm::dvec2> vertices;
};

inline void add_path(Section& s, const std::vector<glm::dvec2>& path) {
    for (std::size_t i = 0; i < path.size(); ++i) {
        const glm::dvec2 p = path[i], q = path[(i + 1) % path.size()];
        if (p != q) s.poly.edges.emplace_back(p.x, p.y, q.x, q.y);
        s.vertices.push_back(p);
    }
}

// The polygon's box from its vertices.
inline void finish(Section& s) {
    s.poly.lo = glm::dvec2(1e300);
    s.poly.hi = glm::dvec2(-1e300);
    for (const glm::dvec2& v : s.vertices) {
        s.poly.lo = glm::min(s.poly.lo, v);
        s.poly.hi = glm::max(s.poly.hi, v);
    }
}

// A star of n points around c at radii r·[0.3, 1).
inline std::vector<glm::dvec2> star(std::mt19937_64& rng, glm::dvec2 c, double r, int n) {
    std::uniform_real_distribution<double> u(0.3, 1.0);
    std::vector<glm::dvec2> out;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n, rr = r * u(rng);
        out.push_back(c + rr * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return out;
}

inline double seg_distance(const glm::dvec4& e, glm::dvec2 p) {
    const glm::dvec2 a(e.x, e.y), b(e.z, e.w), ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}

}  // namespace kerf::test
