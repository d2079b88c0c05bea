// Dispatch by primitive kind: a switch, no virtual calls (per-ray hot path).
#include "render/primitives/primitives.hpp"

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_leaf(const Leaf& leaf, const glm::vec<3, T>& o, const glm::vec<3, T>& d, Span<T> out[kMaxSpans], T wa,
                   T wb) {
    switch (leaf.kind) {
        case PrimKind::Sphere: return intersect_sphere(leaf.p, o, d, out);
        case PrimKind::Box: return intersect_box(leaf.p, o, d, out);
        case PrimKind::Cylinder: return intersect_cylinder(leaf.p, o, d, out);
        case PrimKind::Torus: return intersect_torus(leaf.p, o, d, out, wa, wb);
        case PrimKind::Plane: return intersect_plane(leaf.p, o, d, out);
        case PrimKind::Paraboloid: return intersect_paraboloid(leaf.p, o, d, out);
        case PrimKind::Hyperboloid: return intersect_hyperboloid(leaf.p, o, d, out);
        case PrimKind::Mesh: return 0;  // triangle meshes are Embree geometry, not analytic
        case PrimKind::Prism:  // any number of spans: intersect_prism (prism.hpp)
        case PrimKind::Lathe: return 0;  // and intersect_lathe (lathe.hpp)
    }
    return 0;
}

glm::dvec3 object_normal(const Leaf& leaf, const glm::dvec3& p, std::uint8_t part) {
    switch (leaf.kind) {
        case PrimKind::Sphere: return normal_sphere(leaf.p, p, part);
        case PrimKind::Box: return normal_box(leaf.p, p, part);
        case PrimKind::Cylinder: return normal_cylinder(leaf.p, p, part);
        case PrimKind::Torus: return normal_torus(leaf.p, p, part);
        case PrimKind::Plane: return normal_plane(leaf.p, p, part);
        case PrimKind::Paraboloid: return normal_paraboloid(leaf.p, p, part);
        case PrimKind::Hyperboloid: return normal_hyperboloid(leaf.p, p, part);
        case PrimKind::Mesh:
        case PrimKind::Prism:
        case PrimKind::Lathe: break;  // by triangle / edge: build.hpp, prism.hpp, lathe.hpp
    }
    return {0, 0, 1};
}

template int intersect_leaf<float>(const Leaf&, const glm::vec<3, float>&, const glm::vec<3, float>&, Span<float>*, float,
                                   float);
template int intersect_leaf<double>(const Leaf&, const glm::vec<3, double>&, const glm::vec<3, double>&, Span<double>*,
                                    double, double);

}  // namespace kerf::csg
