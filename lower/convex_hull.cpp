#include "lower/convex_hull.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace kerf {

namespace {

constexpr double kFlat = 1e-10;  // relative to the diameter: see convex_hull.hpp

std::size_t farthest(const std::vector<glm::dvec3>& pts, auto&& distance, double& best) {
    std::size_t at = 0;
    best = -1;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double d = distance(pts[i]);
        if (d > best) best = d, at = i;
    }
    return at;
}

// Any unit vector perpendicular to n.
glm::dvec3 perpendicular(const glm::dvec3& n) {
    const glm::dvec3 a = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(n, a));
}

double cross2(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain in the plane through `origin` with normal n:
// indices of the corners, counter-clockwise seen from +n.
std::vector<std::size_t> polygon_hull(const std::vector<glm::dvec3>& pts, const glm::dvec3& origin,
                                      const glm::dvec3& n) {
    const glm::dvec3 e1 = perpendicular(n), e2 = glm::cross(n, e1);
    std::vector<std::pair<glm::dvec2, std::size_t>> q;
    q.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const glm::dvec3 d = pts[i] - origin;
        q.push_back({{glm::dot(d, e1), glm::dot(d, e2)}, i});
    }
    std::sort(q.begin(), q.end(), [](const auto& a, const auto& b) {
        return a.first.x < b.first.x || (a.first.x == b.first.x && a.first.y < b.first.y);
    });
    std::vector<std::pair<glm::dvec2, std::size_t>> h(2 * q.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {  // lower chain
        while (k >= 2 && cross2(h[k - 2].first, h[k - 1].first, q[i].first) <= 0) --k;
        h[k++] = q[i];
    }
    for (std::size_t i = q.size() - 1, t = k + 1; i-- > 0;) {  // upper chain
        while (k >= t && cross2(h[k - 2].first, h[k - 1].first, q[i].first) <= 0) --k;
        h[k++] = q[i];
    }
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i + 1 < k; ++i) out.push_back(h[i].second);
    return out;
}

// qhull over a full-dimensional set; false (and qhull's first message
// line in `failure`) when qhull gives up.
bool polytope(const std::vector<glm::dvec3>& pts, ConvexHull& out, const char* opts, std::string& failure) {
    // qhull reads the points in place: none of the options used here scales,
    // projects or joggles them, so they are never written.
    static_assert(sizeof(glm::dvec3) == 3 * sizeof(coordT));
    coordT* coords = const_cast<coordT*>(&pts[0].x);
    char* message = nullptr;
    std::size_t message_size = 0;
    FILE* err = open_memstream(&message, &message_size);
    qhT qh_storage;
    qhT* qh = &qh_storage;
    qh_zero(qh, err);
    std::string options = opts;
    const int code = qh_new_qhull(qh, 3, int(pts.size()), coords, False, options.data(), nullptr, err);
    if (code == 0) {
        // Corners numbered in the order the facets first meet them, looked
        // up by qhull's vertex id (qh_pointid once per corner, not per use).
        std::vector<std::uint32_t> remap(std::size_t(qh->vertex_id), UINT32_MAX);
        out.points.reserve(std::size_t(qh->num_vertices));
        out.faces.reserve(std::size_t(qh->num_facets));
        out.normals.reserve(std::size_t(qh->num_facets));
        facetT* facet;
        vertexT *vertex, **vertexp;
        FORALLfacets {
            const glm::dvec3 n(facet->normal[0], facet->normal[1], facet->normal[2]);
            std::vector<std::uint32_t> loop;
            loop.reserve(std::size_t(qh_setsize(qh, facet->vertices)));
            FOREACHvertex_(facet->vertices) {
                std::uint32_t& corner = remap[vertex->id];
                if (corner == UINT32_MAX) {
                    corner = std::uint32_t(out.points.size());
                    out.points.push_back(pts[std::size_t(qh_pointid(qh, vertex->point))]);
                }
                loop.push_back(corner);
            }
            if (loop.size() == 3) {  // a triangle: one turn tells its orientation
                const glm::dvec3 a = out.points[loop[0]], b = out.points[loop[1]], c = out.points[loop[2]];
                if (glm::dot(glm::cross(b - a, c - a), n) < 0) std::swap(loop[1], loop[2]);
            } else {
                // Counter-clockwise about the outward normal: by angle in the facet's plane.
                glm::dvec3 centre(0);
                for (std::uint32_t v : loop) centre += out.points[v];
                centre /= double(loop.size());
                const glm::dvec3 e1 = perpendicular(n), e2 = glm::cross(n, e1);
                std::vector<std::pair<double, std::uint32_t>> by_angle;
                for (std::uint32_t v : loop) {
                    const glm::dvec3 d = out.points[v] - centre;
                    by_angle.push_back({std::atan2(glm::dot(d, e2), glm::dot(d, e1)), v});
                }
                std::sort(by_angle.begin(), by_angle.end());
                for (std::size_t i = 0; i < loop.size(); ++i) loop[i] = by_angle[i].second;
            }
            out.faces.push_back(std::move(loop));
            out.normals.push_back(n);
        }
    }
    qh_freeqhull(qh, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(qh, &curlong, &totlong);
    std::fclose(err);
    if (code != 0) {
        failure = message ? std::string(message) : std::string("qhull error");
        failure = failure.substr(0, failure.find('\n', 1));
    }
    std::free(message);
    return code == 0;
}

}  // namespace

ConvexHull convex_hull(const std::vector<glm::dvec3>& pts) {
    ConvexHull out;
    if (pts.empty()) return out;
    const glm::dvec3 p0 = pts[0];
    double d1 = 0, d2 = 0, d3 = 0;
    const glm::dvec3 p1 = pts[farthest(pts, [&](const glm::dvec3& p) { return glm::length(p - p0); }, d1)];
    if (!(d1 > 0)) {
        out.dim = 0;
        out.points = {p0};
        return out;
    }
    const glm::dvec3 u = (p1 - p0) / d1;
    const glm::dvec3 p2 = pts[farthest(pts, [&](const glm::dvec3& p) { return glm::length(glm::cross(p - p0, u)); }, d2)];
    if (d2 <= kFlat * d1) {
        double lo = 0, hi = 0;
        std::size_t ilo = 0, ihi = 0;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const double t = glm::dot(pts[i] - p0, u);
            if (t < lo) lo = t, ilo = i;
            if (t > hi) hi = t, ihi = i;
        }
        out.dim = 1;
        out.points = {pts[ilo], pts[ihi]};
        return out;
    }
    const glm::dvec3 n = glm::normalize(glm::cross(p1 - p0, p2 - p0));
    farthest(pts, [&](const glm::dvec3& p) { return std::abs(glm::dot(p - p0, n)); }, d3);
    if (d3 <= kFlat * d1) {
        out.dim = 2;
        out.normal = n;
        for (std::size_t i : polygon_hull(pts, p0, n)) out.points.push_back(pts[i]);
        return out;
    }
    out.dim = 3;
    // Nearly flat sets (above kFlat) can make qhull's first simplex too
    // thin for its default search; Qs searches all points for it.
    std::string failure;
    if (polytope(pts, out, "qhull", failure)) return out;
    out = ConvexHull{};
    out.dim = 3;
    if (!polytope(pts, out, "qhull Qs", failure)) throw std::runtime_error("qhull failed: " + failure);
    return out;
}

double hull_volume(const ConvexHull& h) {
    if (h.dim < 3) return 0;
    double v = 0;
    const glm::dvec3 o = h.points[0];
    for (const auto& f : h.faces)
        for (std::size_t k = 1; k + 1 < f.size(); ++k)
            v += glm::dot(h.points[f[0]] - o, glm::cross(h.points[f[k]] - o, h.points[f[k + 1]] - o));
    return v / 6;
}

}  // namespace kerf
