// The defining inequalities of docs/spec.md §4's solids, one case each.
#include "csg/membership.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::csg {

namespace {

double radial(const glm::dvec3& p) { return std::hypot(p.x, p.y); }

// Cylinder/cone radius at height z.
double cone_radius(const double* c, double z) { return c[2] + (c[3] - c[2]) * (z - c[0]) / (c[1] - c[0]); }

// Hyperboloid radius² at height z: waist² at 0, r² at ±h/2, quadratic in z.
double hyper_radius2(const double* c, double z) {
    const double s = 2 * z / c[0];
    return c[2] * c[2] + (c[1] * c[1] - c[2] * c[2]) * s * s;
}

}  // namespace

bool contains(const Leaf& leaf, const glm::dvec3& x) {
    const double* c = leaf.p;
    switch (leaf.kind) {
        case PrimKind::Sphere: return glm::dot(x, x) < c[0] * c[0];
        case PrimKind::Box:
            return c[0] < x.x && x.x < c[3] && c[1] < x.y && x.y < c[4] && c[2] < x.z && x.z < c[5];
        case PrimKind::Cylinder: return c[0] < x.z && x.z < c[1] && radial(x) < cone_radius(c, x.z);
        case PrimKind::Torus: {
            const double e = radial(x) - c[0];
            return e * e + x.z * x.z < c[1] * c[1];
        }
        case PrimKind::Plane: return c[0] * x.x + c[1] * x.y + c[2] * x.z < c[3];
        case PrimKind::Paraboloid: {
            const double rho = radial(x);
            return x.z < c[0] && x.z > c[0] * rho * rho / (c[1] * c[1]);
        }
        case PrimKind::Hyperboloid: {
            const double rho = radial(x);
            return std::abs(x.z) < 0.5 * c[0] && rho * rho < hyper_radius2(c, x.z);
        }
        case PrimKind::Mesh:
        case PrimKind::Prism:
        case PrimKind::Lathe: return false;  // need their data: contains(Scene, ...), contains_prism/_lathe
    }
    return false;
}

// Even-odd point in polygon the textbook way (a ray towards +x from the
// point, an edge counted when its end points lie on either side of the
// point's y, half-open); a prism asks it of the section at the point's z,
// strictly inside the slab.
bool even_odd(const Polygon2& poly, double px, double py) {
    bool odd = false;
    for (const glm::dvec4& e : poly.edges) {
        if ((e.y > py) == (e.w > py)) continue;
        const double xc = e.x + (py - e.y) * (e.z - e.x) / (e.w - e.y);
        if (xc > px) odd = !odd;
    }
    return odd;
}

bool contains_prism(const Polygon2& poly, const double* c, const glm::dvec3& x) {
    if (!(c[0] < x.z && x.z < c[1])) return false;
    // The section at this z is scale(kx, ky) · rotate(−c[4]·τ) · poly: undo both.
    const double tau = (x.z - c[0]) / (c[1] - c[0]);
    const double kx = 1 + c[2] * tau, ky = 1 + (c[2] + c[3]) * tau;
    if (!(kx > 0 && ky > 0)) return false;
    const double u = x.x / kx, v = x.y / ky, a = c[4] * tau;
    return even_odd(poly, std::cos(a) * u - std::sin(a) * v, std::sin(a) * u + std::cos(a) * v);
}

// Revolved back into the (ρ, z) half-plane: the section's rule there.
bool contains_lathe(const Polygon2& poly, const glm::dvec3& x) { return even_odd(poly, std::hypot(x.x, x.y), x.z); }

double surface_distance(const Leaf& leaf, const glm::dvec3& x) {
    const double* c = leaf.p;
    switch (leaf.kind) {
        case PrimKind::Sphere: return glm::length(x) - c[0];
        case PrimKind::Box: {
            const glm::dvec3 lo(c[0], c[1], c[2]), hi(c[3], c[4], c[5]);
            const glm::dvec3 q = glm::max(lo - x, x - hi);  // per axis, > 0 outside the slab
            const double inner = std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
            return glm::length(glm::max(q, glm::dvec3(0.0))) + inner;
        }
        case PrimKind::Cylinder: {
            // Distance to the side line is (ρ - r(z)) · cos(atan(slope)); a
            // straight cylinder's is ρ - r. ρ as sqrt, not hypot: this is
            // adaptive AA's edge prediction's inner loop, where glibc's
            // hypot (careful about overflow past 1e154) cost as much time
            // as the rest of the distance (docs/quality.md).
            const double rho = std::sqrt(x.x * x.x + x.y * x.y);
            double side;
            if (c[2] == c[3]) {
                side = rho - c[2];
            } else {
                const double slope = (c[3] - c[2]) / (c[1] - c[0]);
                side = (rho - cone_radius(c, x.z)) / std::sqrt(1 + slope * slope);
            }
            const double caps = std::max(c[0] - x.z, x.z - c[1]);
            if (side > 0 && caps > 0) return std::hypot(side, caps);  // outside the rim
            return std::max(side, caps);
        }
        case PrimKind::Torus: return std::hypot(radial(x) - c[0], x.z) - c[1];
        case PrimKind::Plane: return c[0] * x.x + c[1] * x.y + c[2] * x.z - c[3];
        case PrimKind::Paraboloid: {
            const double k = c[0] / (c[1] * c[1]);
            const double rho = radial(x);
            const double f = k * rho * rho - x.z;  // ∇f = (2k·x, 2k·y, -1)
            const double side = f / std::sqrt(4 * k * k * rho * rho + 1);
            return std::max(side, x.z - c[0]);
        }
        case PrimKind::Hyperboloid: {
            const double half = 0.5 * c[0];
            const double kappa = (c[1] * c[1] - c[2] * c[2]) / (half * half);
            const double rho = radial(x);
            const double f = rho * rho - hyper_radius2(c, x.z);  // ∇f = (2x, 2y, -2κz)
            const double g = 2 * std::sqrt(rho * rho + kappa * kappa * x.z * x.z);
            const double side = g > 0 ? f / g : (f == 0 ? 0.0 : std::copysign(std::sqrt(std::abs(f)), f));
            return std::max(side, std::abs(x.z) - half);
        }
        case PrimKind::Mesh:
        case PrimKind::Prism:
        case PrimKind::Lathe: break;
    }
    return std::numeric_limits<double>::infinity();
}

namespace {

bool node_contains(const Scene& s, std::uint32_t node, const glm::dvec3& p) {
    const Node& n = s.nodes[node];
    switch (n.op) {
        case Op::Leaf: {
            const Leaf& l = s.leaves[n.first];
            if (l.kind == PrimKind::Prism)
                return l.polygon < s.polygons.size() &&
                       contains_prism(s.polygons[l.polygon], l.p, l.object_from_world.point(p));
            if (l.kind == PrimKind::Lathe)
                return l.polygon < s.polygons.size() &&
                       contains_lathe(s.polygons[l.polygon], l.object_from_world.point(p));
            return contains(l, l.object_from_world.point(p));
        }
        case Op::Union:
            for (std::uint32_t k = 0; k < n.count; ++k)
                if (node_contains(s, s.children[n.first + k], p)) return true;
            return false;
        case Op::Intersection:
            for (std::uint32_t k = 0; k < n.count; ++k)
                if (!node_contains(s, s.children[n.first + k], p)) return false;
            return n.count > 0;
        case Op::Difference:
            if (n.count == 0 || !node_contains(s, s.children[n.first], p)) return false;
            for (std::uint32_t k = 1; k < n.count; ++k)
                if (node_contains(s, s.children[n.first + k], p)) return false;
            return true;
    }
    return false;
}

}  // namespace

bool contains(const Scene& scene, const glm::dvec3& p_world) {
    return scene.root != kNone && node_contains(scene, scene.root, p_world);
}

}  // namespace kerf::csg
