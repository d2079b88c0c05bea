#include "interpreter/modules/region2d.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>

#include "grammar/source.hpp"
#include "interpreter/modules/flat_hull_ops.hpp"
#include "interpreter/modules/plane_map.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;
using namespace ClipperLib;

// One leaf's outline as closed paths of mapped points (real coordinates).
std::vector<std::vector<glm::dvec2>> outline(const graph::SceneGraph& g, const graph::Node& n, const Map2& a,
                                             double tol) {
    std::vector<std::vector<glm::dvec2>> out;
    if (n.prim == P::Box) {
        out.push_back({apply(a, {n.p[0], n.p[1]}), apply(a, {n.p[3], n.p[1]}), apply(a, {n.p[3], n.p[4]}),
                       apply(a, {n.p[0], n.p[4]})});
    } else if (n.prim == P::Prism) {
        // polygon() stores each path's edges in order: a path is a run of
        // edges each starting where the last ended.
        bool open = false;
        glm::dvec2 last(0);
        for (const glm::dvec4& e : g.polygons[n.index].edges) {
            const glm::dvec2 p(e.x, e.y), q(e.z, e.w);
            if (!open || p != last) out.push_back({apply(a, p)});
            out.back().push_back(apply(a, q));
            last = q, open = true;
        }
    } else if (n.prim == P::Cylinder) {
        out.emplace_back();
        circle_chords(n.p[2], tol, [&](glm::dvec2 p, glm::dvec2) { out.back().push_back(apply(a, p)); });
    } else {
        throw SourceError(n.loc, "this shape has no 2D outline");
    }
    return out;
}

Paths execute(ClipType op, const Paths& subject, const Paths& clip, PolyFillType fill) {
    Clipper c;
    c.AddPaths(subject, ptSubject, true);
    c.AddPaths(clip, ptClip, true);
    Paths out;
    c.Execute(op, out, fill, fill);
    return out;
}

class Flattener {
public:
    Flattener(const graph::SceneGraph& g, double tol) : g_(g), tol_(tol) {}
    double extent = 0;  // the largest |coordinate| of a mapped leaf point
    Region2 frame;       // its scale: the grid the leaves are put on

    void measure(std::uint32_t id, const Map2& a) {
        const graph::Node& n = g_.nodes[id];
        if (n.kind == graph::NodeKind::Primitive) {
            for (const auto& path : outline(g_, n, a, tol_))
                for (glm::dvec2 p : path) extend(p);
            return;
        }
        if (convex_op(n)) {
            for (const ConvexPolygon& part : convex_parts(id))
                for (glm::dvec2 p : part) extend(apply(a, p));
            return;
        }
        if (n.kind == graph::NodeKind::Resize) {
            if (n.child_count > 0) measure(g_.child_refs[n.first_child], a * flat_resize_map(g_, id));
            return;
        }
        for (std::uint32_t k = 0; k < n.child_count; ++k) measure(g_.child_refs[n.first_child + k], inner(n, a));
    }

    Paths region(std::uint32_t id, const Map2& a) {
        const graph::Node& n = g_.nodes[id];
        if (n.kind == graph::NodeKind::Primitive) {
            Paths leaf;
            for (const auto& path : outline(g_, n, a, tol_)) {
                leaf.emplace_back();
                for (glm::dvec2 p : path) leaf.back().push_back(frame.grid(p));
            }
            // Normalised: a polygon's paths by the even-odd rule, a mirror's reversed orientation undone.
            return execute(ctUnion, leaf, {}, n.prim == P::Prism ? pftEvenOdd : pftNonZero);
        }
        // A hull or a sum is no boolean of its children: its convex parts
        // in the plane, by lowering's rules (flat_hull_ops.hpp); a resize
        // is the scale it applies to its first child.
        if (convex_op(n)) {
            Paths parts;
            for (const ConvexPolygon& part : convex_parts(id)) {
                parts.emplace_back();
                for (glm::dvec2 p : part) parts.back().push_back(frame.grid(apply(a, p)));
            }
            return execute(ctUnion, parts, {}, pftNonZero);
        }
        if (n.kind == graph::NodeKind::Resize)
            return n.child_count > 0 ? region(g_.child_refs[n.first_child], a * flat_resize_map(g_, id)) : Paths{};
        std::vector<Paths> parts;
        for (std::uint32_t k = 0; k < n.child_count; ++k) parts.push_back(region(g_.child_refs[n.first_child + k], inner(n, a)));
        if (parts.empty()) return {};
        if (n.kind == graph::NodeKind::Intersection) {
            Paths acc = parts[0];
            for (std::size_t k = 1; k < parts.size(); ++k) acc = execute(ctIntersection, acc, parts[k], pftNonZero);
            return acc;
        }
        if (n.kind == graph::NodeKind::Difference) {
            Paths rest;
            for (std::size_t k = 1; k < parts.size(); ++k) rest.insert(rest.end(), parts[k].begin(), parts[k].end());
            return execute(ctDifference, parts[0], rest, pftNonZero);
        }
        // Union, or a transform or appearance scope over one child (a union of its block).
        Paths all;
        for (const Paths& p : parts) all.insert(all.end(), p.begin(), p.end());
        return parts.size() == 1 ? parts[0] : execute(ctUnion, all, {}, pftNonZero);
    }

private:
    const graph::SceneGraph& g_;
    double tol_;
    std::unordered_map<std::uint32_t, std::vector<ConvexPolygon>> convex_;  // built once for both passes

    void extend(glm::dvec2 p) { extent = std::max({extent, std::abs(p.x), std::abs(p.y)}); }

    static bool convex_op(const graph::Node& n) {
        return n.kind == graph::NodeKind::Hull || (n.kind == graph::NodeKind::Minkowski && n.child_count > 1);
    }

    const std::vector<ConvexPolygon>& convex_parts(std::uint32_t id) {
        auto it = convex_.find(id);
        if (it == convex_.end()) it = convex_.emplace(id, flat_convex_parts(g_, id)).first;
        return it->second;
    }

    Map2 inner(const graph::Node& n, const Map2& a) const {
        return n.kind == graph::NodeKind::Transform ? a * plane_part(g_.matrices[n.index]) : a;
    }
};

}  // namespace

Region2 flatten_region(const graph::SceneGraph& g, std::span<const std::uint32_t> roots, double margin,
                       double curve_tolerance, const SourceLoc& loc) {
    Flattener f(g, curve_tolerance);
    for (std::uint32_t id : roots) f.measure(id, Map2(1.0));
    const double extent = f.extent + 2 * std::abs(margin);
    Region2 r;
    // 2^50 grid steps across the extent: Clipper's full range (±2^62) keeps
    // its products exact, and the offset's arithmetic, done in doubles, stays
    // within their 2^53 integers.
    r.scale = extent > 0 ? std::ldexp(1.0, 50 - std::ilogb(extent) - 1) : 1;
    if (!std::isfinite(r.scale) || !std::isfinite(extent))  // below 2^-970 or past the doubles: no grid holds it
        throw SourceError(loc, "the 2D shape's coordinates are out of the range this operation supports");
    f.frame.scale = r.scale;
    Paths all;
    for (std::uint32_t id : roots) {
        Paths p = f.region(id, Map2(1.0));
        all.insert(all.end(), p.begin(), p.end());
    }
    r.paths = roots.size() == 1 ? all : execute(ctUnion, all, {}, pftNonZero);
    return r;
}

csg::Polygon2 region_polygon(const Region2& r) {
    csg::Polygon2 poly;
    poly.lo = glm::dvec2(std::numeric_limits<double>::infinity());
    poly.hi = -poly.lo;
    for (const Path& path : r.paths)
        for (std::size_t i = 0; i < path.size(); ++i) {
            const glm::dvec2 p = r.point(path[i]), q = r.point(path[(i + 1) % path.size()]);
            if (p != q) poly.edges.emplace_back(p.x, p.y, q.x, q.y);
            poly.lo = glm::min(poly.lo, p);
            poly.hi = glm::max(poly.hi, p);
        }
    return poly;
}

}  // namespace kerf::eval
