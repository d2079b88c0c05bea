// A DXF drawing (import/dxf.hpp) in the graph as 2D shapes do it
// (shapes2d.cpp): its flattened loops one even-odd Prism, its exact circles
// Cylinders — added where the loops around them are even, cut where odd,
// which is the even-odd fill because such a circle crosses nothing and
// holds nothing; its exact bulges so too, each a disc ∩ square.
#include "interpreter/modules/import2d.hpp"

#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "interpreter/import/dxf.hpp"
#include "interpreter/import/mesh_import.hpp"
#include "interpreter/modules/args.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;
enum { File, Solid, Convexity, Layer, Origin, Scale };

void add_flat(ModuleCall& c, P kind, std::initializer_list<double> p, std::uint32_t index = 0) {
    c.add_primitive(kind, p, index);
    c.graph().graph.nodes[c.graph().pending.back()].flat = true;
}

void add_circle(ModuleCall& c, const DxfCircle& circle) {
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    add_flat(c, P::Cylinder, {0, 1, circle.r, circle.r});
    g.graph.matrices.push_back(glm::translate(glm::dmat4(1), glm::dvec3(circle.centre, 0)));
    g.wrap(mark, graph::NodeKind::Transform, static_cast<std::uint32_t>(g.graph.matrices.size() - 1), c.st.loc);
}

// A bulge's circular segment: its disc cut by a square in the chord's frame
// (x along the chord, y toward the arc from the chord line), which holds
// the whole segment and no more of the disc than lies beyond the chord.
void add_segment(ModuleCall& c, const DxfSegment& s) {
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    add_circle(c, {s.centre, s.r});
    add_flat(c, P::Box, {-1.001 * s.r, 0, 0, 1.001 * s.r, 1.001 * s.sagitta, 1});
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(s.normal.y, -s.normal.x, 0, 0);  // (x, normal) right-handed
    m[1] = glm::dvec4(s.normal, 0, 0);
    m[3] = glm::dvec4((s.p + s.q) / 2.0, 0, 1);
    g.graph.matrices.push_back(m);
    g.wrap(g.mark() - 1, graph::NodeKind::Transform, static_cast<std::uint32_t>(g.graph.matrices.size() - 1), c.st.loc);
    g.make_node(mark, graph::NodeKind::Intersection, c.st.loc);
}

}  // namespace

void import_drawing(ModuleCall& c, const std::string& path) {
    const Args& a = c.args;
    DxfOptions o;
    if (a.has(Layer) && !a[Layer].is_undef()) {
        if (!a[Layer].is_string()) arg_error(a, "layer must be a string, got " + to_repr(a[Layer]));
        o.layer = a[Layer].as_string();
    }
    o.origin = glm::dvec2(arg_vec3(a, Origin, "origin", glm::dvec3(0), true));
    o.scale = arg_positive(a, Scale, "scale", 1);
    o.tolerance = c.curve_tolerance();
    o.max_entities = c.limits().list_elements;
    DxfShape shape;
    try {
        shape = import_dxf(path, o);
    } catch (const MeshFormatError& e) {
        throw SourceError(c.st.loc, "import(\"" + a[File].as_string() + "\"): " + e.what());
    }
    const std::string name = "\"" + a[File].as_string() + "\"";
    if (shape.open_paths)
        c.warn(std::to_string(shape.open_paths) + " open path(s) in " + name +
               " closed by a straight edge from end to start, as OpenSCAD does");
    if (shape.loops.empty() && shape.circles.empty() && shape.segments.empty())
        return c.warn(name + (o.layer.empty() ? "" : " layer \"" + o.layer + "\"") +
                      " holds no closed outline: the empty shape");
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    if (!shape.loops.empty()) {
        csg::Polygon2 poly;
        poly.lo = glm::dvec2(std::numeric_limits<double>::infinity());
        poly.hi = -poly.lo;
        for (const auto& loop : shape.loops)
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const glm::dvec2 p = loop[i], q = loop[(i + 1) % loop.size()];
                if (p != q) poly.edges.emplace_back(p.x, p.y, q.x, q.y);
                poly.lo = glm::min(poly.lo, p), poly.hi = glm::max(poly.hi, p);
            }
        g.graph.polygons.push_back(std::move(poly));
        add_flat(c, P::Prism, {0, 1}, static_cast<std::uint32_t>(g.graph.polygons.size() - 1));
    }
    for (std::size_t i = 0; i < shape.circles.size(); ++i)
        if (shape.circle_depth[i] % 2 == 0) add_circle(c, shape.circles[i]);
    for (const DxfSegment& s : shape.segments)
        if (!s.hole) add_segment(c, s);
    const std::size_t holes = g.mark();
    for (std::size_t i = 0; i < shape.circles.size(); ++i)
        if (shape.circle_depth[i] % 2 == 1) add_circle(c, shape.circles[i]);
    for (const DxfSegment& s : shape.segments)
        if (s.hole) add_segment(c, s);
    if (g.mark() == holes) return g.group(mark, c.st.loc);
    // The filled part first (a union when several), then the holes cut from it.
    std::vector<std::uint32_t> cut(g.pending.begin() + std::ptrdiff_t(holes), g.pending.end());
    g.pending.resize(holes);
    g.group(mark, c.st.loc);
    g.pending.insert(g.pending.end(), cut.begin(), cut.end());
    g.make_node(mark, graph::NodeKind::Difference, c.st.loc);
}

}  // namespace kerf::eval
