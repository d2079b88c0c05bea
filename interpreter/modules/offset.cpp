// offset(r | delta, chamfer) (docs/spec.md §10), OpenSCAD 2021.01's
// semantics: `r` rounds (the Minkowski sum with a disc of radius r, or for
// r < 0 the points at least |r| inside), `delta` keeps sharp corners (a
// miter join), `delta` with `chamfer = true` cuts each corner square at
// distance delta (Clipper's square join, as OpenSCAD). kerf keeps the arcs
// exact (docs/lowering.md, "Offsets"):
// - a circle alone (under similarities) stays a circle, of radius r + δ;
// - otherwise the children become one polygon region (region2d.hpp: a
//   circle among them flattened within the curve tolerance); `delta` is
//   Clipper's polygon offset of it; `r` is the region with the rectangle
//   of width 2|r| around each boundary edge added (r > 0) or taken away
//   (r < 0) by Clipper, then a disc of radius |r| at the corners added or
//   subtracted as Cylinder leaves: the set of points within |r| of the
//   boundary is exactly those rectangles and discs (round_offset);
// - under --facets openscad, `r` is OpenSCAD's own: Clipper's round join
//   with the arc tolerance OpenSCAD derives from $fn, $fa and $fs.
#include <cmath>

#include "interpreter/degrees.hpp"
#include "interpreter/modules/args.hpp"
#include "interpreter/modules/facets.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/modules/plane_map.hpp"
#include "interpreter/modules/region2d.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;
using namespace ClipperLib;

// The one circle leaf of a subtree of transforms, appearance scopes and
// one-child booleans, or null; `a` becomes the plane map down to it.
graph::Node* lone_circle(graph::SceneGraph& g, std::uint32_t id, Map2& a) {
    for (;;) {
        graph::Node& n = g.nodes[id];
        if (n.kind == graph::NodeKind::Primitive) return n.prim == P::Cylinder ? &n : nullptr;
        if (n.child_count != 1) return nullptr;
        if (n.kind == graph::NodeKind::Transform) a = a * plane_part(g.matrices[n.index]);
        id = g.child_refs[n.first_child];
    }
}

// The uniform scale of a similarity's linear part, or 0 when it is not one.
double similarity_scale(const Map2& a) {
    const glm::dvec2 c0(a[0]), c1(a[1]);
    const double l0 = glm::length(c0), l1 = glm::length(c1);
    const bool similar = std::abs(l0 - l1) <= 1e-12 * l0 && std::abs(glm::dot(c0, c1)) <= 1e-12 * l0 * l1;
    return similar ? l0 : 0;
}

void push_flat(GraphBuilder& g) { g.graph.nodes[g.pending.back()].flat = true; }

void push_prism(ModuleCall& c, const Region2& r) {
    csg::Polygon2 poly = region_polygon(r);
    if (poly.edges.empty()) return;
    auto& polys = c.graph().graph.polygons;
    polys.push_back(std::move(poly));
    c.add_primitive(P::Prism, {0, 1}, static_cast<std::uint32_t>(polys.size() - 1));
    push_flat(c.graph());
}

void push_disc(ModuleCall& c, glm::dvec2 centre, double radius) {
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    c.add_primitive(P::Cylinder, {0, 1, radius, radius});
    push_flat(g);
    glm::dmat4 m(1.0);
    m[3][0] = centre.x, m[3][1] = centre.y;
    g.add_matrix(m);
    g.make_node(mark, graph::NodeKind::Transform, c.st.loc, static_cast<std::uint32_t>(g.graph.matrices.size() - 1));
}

// offset(r): the region and the rectangles around its edges merged by
// Clipper, then discs at the corners where the nearest boundary point can
// be a vertex: the region's convex corners for r > 0, its reflex corners
// for r < 0 (a point's nearest point is never a corner the region wraps
// around). A corner that turns by less than the curve tolerance's angle (a
// flattened curve's vertex: its arc's sagitta within tolerance · |r|) gets
// the triangle under its arc merged by Clipper instead of a disc leaf, so
// an offset curve costs no more than the curve.
void round_offset(ModuleCall& c, Region2 region, double r, double tolerance) {
    const double w = std::abs(r);
    Paths added;  // rectangles and corner triangles, counter-clockwise
    auto add = [&](std::initializer_list<glm::dvec2> pts) {
        Path path;
        for (glm::dvec2 p : pts) path.push_back(region.grid(p));
        if (!Orientation(path)) ReversePath(path);
        added.push_back(std::move(path));
    };
    std::vector<glm::dvec2> discs;
    for (const Path& path : region.paths)
        for (std::size_t i = 0; i < path.size(); ++i) {
            const std::size_t n = path.size();
            const glm::dvec2 o = region.point(path[(i + n - 1) % n]), p = region.point(path[i]),
                             q = region.point(path[(i + 1) % n]);
            if (p == q || o == p) continue;
            const glm::dvec2 d0 = glm::normalize(p - o), d1 = glm::normalize(q - p);
            const glm::dvec2 left1(-d1.y, d1.x);
            add({p + w * left1, p - w * left1, q - w * left1, q + w * left1});
            // The region lies left of its paths (Clipper: outer paths counter-clockwise, holes clockwise).
            const double turn = d0.x * d1.y - d0.y * d1.x;
            if (r > 0 ? turn <= 0 : turn >= 0) continue;
            const double angle = std::atan2(std::abs(turn), glm::dot(d0, d1));
            if (1 - std::cos(angle / 2) > tolerance) {
                discs.push_back(p);
            } else {
                const double side = r > 0 ? -1 : 1;  // the arc's side: right of the path for r > 0
                add({p, p + side * w * glm::dvec2(-d0.y, d0.x), p + side * w * left1});
            }
        }
    Clipper clip;
    clip.AddPaths(region.paths, ptSubject, true);
    clip.AddPaths(added, ptClip, true);
    Paths out;
    clip.Execute(r > 0 ? ctUnion : ctDifference, out, pftNonZero, pftNonZero);
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    Region2 merged = region;
    merged.paths = std::move(out);
    push_prism(c, merged);
    if (g.mark() == mark && r < 0) return;  // eroded away
    for (glm::dvec2 v : discs) push_disc(c, v, w);
    if (g.mark() > mark + 1) g.make_node(mark, r > 0 ? graph::NodeKind::Union : graph::NodeKind::Difference, c.st.loc);
}

void offset(ModuleCall& c) {
    const Args& a = c.args;
    const bool has_r = a.has(0) && !a[0].is_undef(), has_delta = a.has(1) && !a[1].is_undef();
    if (has_r && has_delta) {
        // OpenSCAD takes r and ignores delta.
        if (!c.lenient()) arg_error(a, "give r or delta, not both");
        c.warn("r and delta given: delta is ignored, as in OpenSCAD");
    }
    const bool chamfer = arg_bool(a, 2, "chamfer", false);
    if (has_r && chamfer) c.warn("chamfer applies to delta and is ignored with r");
    const bool round = has_r || !has_delta;  // OpenSCAD's default: r = 1
    const double dist = round ? arg_number(a, 0, "r", 1) : arg_number(a, 1, "delta", 1);
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    {
        GhostFrameScope hide(c.state(), "offset");
        c.children();
    }
    const std::vector<std::uint32_t> shapes = c.flat_children(mark, "offsets");
    if (shapes.empty()) return;
    if (dist == 0) {  // the shape itself, as in OpenSCAD
        for (std::uint32_t id : shapes) g.push(id);
        return g.group(mark, c.st.loc);
    }
    // --facets openscad: OpenSCAD's own round join, Clipper's arcs of
    // get_fragments_from_r(|r|) steps per turn (its arc tolerance).
    const bool openscad_arcs = round && c.facet_mode() == FacetMode::OpenScad;
    if (round && !openscad_arcs) c.exact_curve();  // the round joins are exact arcs, not $fn steps
    Map2 m(1.0);
    if (shapes.size() == 1 && !openscad_arcs) {
        if (graph::Node* circle = lone_circle(g.graph, shapes[0], m); circle) {
            if (const double k = similarity_scale(m); k > 0) {
                // Every join of a smooth curve is its round join: r, delta and chamfer agree.
                const double radius = circle->p[2] + dist / k;
                if (radius <= 0) return;
                circle->p[2] = circle->p[3] = radius;
                return g.push(shapes[0]);
            }
        }
    }
    Region2 region;
    try {
        region = flatten_region(g.graph, shapes, dist, c.curve_tolerance(), c.st.loc);
        if (round && !openscad_arcs) return round_offset(c, std::move(region), dist, c.curve_tolerance());
        // OpenSCAD's miter limit: high enough never to square a sharp corner.
        ClipperOffset off(1e6);
        if (openscad_arcs) {
            const int n = openscad_fragments(c, std::abs(dist), c.facet_vars());
            off.ArcTolerance = std::abs(dist) * (1 - cos_deg(180.0 / n)) * region.scale;
        }
        off.AddPaths(region.paths, openscad_arcs ? jtRound : chamfer ? jtSquare : jtMiter, etClosedPolygon);
        Paths out;
        off.Execute(out, dist * region.scale);
        region.paths = std::move(out);
    } catch (const clipperException& e) {
        throw SourceError(c.st.loc, std::string("offset: ") + e.what());
    }
    push_prism(c, region);
}

const ModuleEntry kOffset[] = {
    {"offset", ModuleKind::Operation, {"r", "delta", "chamfer"}, offset},
};

}  // namespace

std::span<const ModuleEntry> offset_modules() { return kOffset; }

}  // namespace kerf::eval
