#include "lower/hull_points.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lower/leaf_placement.hpp"

namespace kerf {

namespace {

using P = csg::PrimKind;

// A circle of radius r at height z (chords within the tolerance).
void ring(std::vector<glm::dvec3>& out, double r, double z, int n) {
    if (r == 0) {
        out.push_back({0, 0, z});
        return;
    }
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        out.push_back({r * std::cos(a), r * std::sin(a), z});
    }
}

}  // namespace

bool similarity(const glm::dmat3& m, double& s) {
    s = glm::length(m[0]);
    for (int i = 0; i < 3; ++i) {
        if (std::abs(glm::length(m[i]) - s) > 1e-12 * s) return false;
        for (int j = i + 1; j < 3; ++j)
            if (std::abs(glm::dot(m[i], m[j])) > 1e-12 * s * s) return false;
    }
    return s > 0;
}

bool planar_similarity(const glm::dmat3& m, double& s) {
    if (m[2] != glm::dvec3(0, 0, 1) || m[0].z != 0 || m[1].z != 0) return false;
    s = glm::length(m[0]);
    return s > 0 && std::abs(glm::length(m[1]) - s) <= 1e-12 * s && std::abs(glm::dot(m[0], m[1])) <= 1e-12 * s * s;
}

int circle_segments(double tolerance) {
    // A chord of angle 2π/n sags r(1 − cos(π/n)) below the circle.
    const double t = std::clamp(tolerance, 1e-9, 0.5);
    return std::max(8, int(std::ceil(std::numbers::pi / std::acos(1 - t))));
}

std::vector<glm::dvec3> sphere_points(double r, double tolerance) {
    const int n = circle_segments(tolerance);
    const int rings = std::max(4, n / 2);  // meridian chords as fine as the equator's
    std::vector<glm::dvec3> pts;
    for (int k = 0; k <= rings; ++k) {
        const double t = std::numbers::pi * k / rings;
        ring(pts, k == 0 || k == rings ? 0 : r * std::sin(t), r * std::cos(t), n);
    }
    return pts;
}

ConvexPiece leaf_piece(const graph::SceneGraph& g, const graph::Node& leaf, const glm::dmat4& xf, double tolerance) {
    ConvexPiece piece;
    std::vector<glm::dvec3>& pts = piece.points;
    const int n = circle_segments(tolerance);
    const double* p = leaf.p;
    const glm::dmat3 linear(xf);
    switch (leaf.prim) {
        case P::Sphere: {
            double s = 0;
            if (similarity(linear, s)) {
                piece.points = {glm::dvec3(xf[3])};
                piece.radius = p[0] * s;
                return piece;
            }
            pts = sphere_points(p[0], tolerance);
            piece.exact = false;
            break;
        }
        case P::Box:
            for (int k = 0; k < 8; ++k) pts.push_back({p[k & 1 ? 3 : 0], p[k & 2 ? 4 : 1], p[k & 4 ? 5 : 2]});
            break;
        case P::Cylinder: {
            double s = 0;
            if (leaf.flat && p[2] == p[3] && planar_similarity(linear, s)) {  // a 2D circle: its axis and a disc
                piece.points = {glm::dvec3(xf * glm::dvec4(0, 0, p[0], 1)), glm::dvec3(xf * glm::dvec4(0, 0, p[1], 1))};
                piece.radius = p[2] * s;
                piece.disc = true;
                return piece;
            }
            ring(pts, p[2], p[0], n);
            ring(pts, p[3], p[1], n);
            piece.exact = false;
            break;
        }
        case P::Hyperboloid:  // its hull is the hull of its two cap circles
            ring(pts, p[1], -p[0] / 2, n);
            ring(pts, p[1], p[0] / 2, n);
            piece.exact = false;
            break;
        case P::Paraboloid: {  // rings along z = h ρ²/r², the cap at z = h
            const int m = std::max(4, n / 4);
            for (int k = 0; k <= m; ++k) ring(pts, p[1] * k / m, p[0] * double(k) * k / (double(m) * m), n);
            piece.exact = false;
            break;
        }
        case P::Torus:  // the tube's circle swept round
            for (int k = 0; k < n; ++k) {
                const double t = 2 * std::numbers::pi * k / n;
                const double rho = p[0] + p[1] * std::cos(t), z = p[1] * std::sin(t);
                ring(pts, rho, z, n);
            }
            piece.exact = false;
            break;
        case P::Mesh:
            pts = g.meshes[leaf.index].points;
            break;
        case P::Prism:
            pts = prism_corners(g.polygons[leaf.index], p);
            break;
        case P::Lathe:  // every vertex of the section sweeps a circle
            for (const glm::dvec4& e : g.polygons[leaf.index].edges) ring(pts, e.x, e.y, n);
            piece.exact = false;
            break;
        case P::Plane:
            throw SourceError(leaf.loc, "a half-space has no convex hull (it is unbounded): hull() and minkowski() "
                                        "need bounded solids");
    }
    for (glm::dvec3& q : pts) q = glm::dvec3(xf * glm::dvec4(q, 1));
    return piece;
}

}  // namespace kerf
