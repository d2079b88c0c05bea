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
#include "interpreter/import/svg.hpp"
#include "interpreter/modules/args.hpp"
#include "interpreter/modules/projection_leaf.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;
enum { File, Solid, Convexity, Layer, Origin, Scale, Center, Dpi };

void add_flat(ModuleCall& c, P kind, std::initializer_list<double> p, std::uint32_t index = 0) {
    c.add_primitive(kind, p, index);
    c.graph().graph.nodes[c.graph().pending.back()].flat = true;
}

void add_circle(ModuleCall& c, const DxfCircle& circle) {
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    add_flat(c, P::Cylinder, {0, 1, circle.r, circle.r});
    g.add_matrix(glm::translate(glm::dmat4(1), glm::dvec3(circle.centre, 0)));
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
    g.add_matrix(m);
    g.wrap(g.mark() - 1, graph::NodeKind::Transform, static_cast<std::uint32_t>(g.graph.matrices.size() - 1), c.st.loc);
    g.make_node(mark, graph::NodeKind::Intersection, c.st.loc);
}

// Loops as one even-odd Prism section.
void add_loops(ModuleCall& c, const std::vector<std::vector<glm::dvec2>>& loops) {
    GraphBuilder& g = c.graph();
    g.graph.polygons.push_back(projection::loops_polygon(loops));
    add_flat(c, P::Prism, {0, 1}, static_cast<std::uint32_t>(g.graph.polygons.size() - 1));
}

// The unit disc under a plane map: an exact circle or ellipse.
void add_disc(ModuleCall& c, const Map2& a) {
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    add_flat(c, P::Cylinder, {0, 1, 1, 1});
    glm::dmat4 m(1.0);
    // A mirrored map draws the same disc as its mirror image turned back
    // (the disc is symmetric), which keeps the leaf's frame right-handed.
    const double flip = a[0][0] * a[1][1] - a[1][0] * a[0][1] < 0 ? -1 : 1;
    m[0] = glm::dvec4(a[0][0], a[0][1], 0, 0);
    m[1] = glm::dvec4(flip * a[1][0], flip * a[1][1], 0, 0);
    m[3] = glm::dvec4(a[2][0], a[2][1], 0, 1);
    g.add_matrix(m);
    g.wrap(mark, graph::NodeKind::Transform, static_cast<std::uint32_t>(g.graph.matrices.size() - 1), c.st.loc);
}

// The reader's result; its MeshFormatError an error at the import, naming the file.
template <typename Read>
auto read_drawing(ModuleCall& c, Read&& read) {
    try {
        return read();
    } catch (const MeshFormatError& e) {
        throw SourceError(c.st.loc, "import(\"" + c.args[File].as_string() + "\"): " + e.what());
    }
}

}  // namespace

void import_svg_drawing(ModuleCall& c, const std::string& path) {
    const Args& a = c.args;
    SvgOptions o;
    o.center = arg_bool(a, Center, "center", false);
    o.dpi = arg_positive(a, Dpi, "dpi", 72);
    o.tolerance = c.curve_tolerance();
    o.max_items = c.limits().list_elements;
    const SvgDrawing drawing = read_drawing(c, [&] { return import_svg(path, o); });
    const std::string name = "\"" + a[File].as_string() + "\"";
    for (const std::string& w : drawing.warnings) c.warn(name + " " + w);
    if (drawing.items.empty()) return c.warn(name + " holds no shape: the empty shape");
    const std::size_t mark = c.graph().mark();
    for (const SvgItem& it : drawing.items) {
        if (it.loops.empty()) add_disc(c, it.disc);
        else add_loops(c, it.loops);
    }
    c.graph().group(mark, c.st.loc);
}

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
    const DxfShape shape = read_drawing(c, [&] { return import_dxf(path, o); });
    if (shape.curves) c.exact_curve();  // kept exact or flattened to the tolerance, not in $fn steps
    const std::string name = "\"" + a[File].as_string() + "\"";
    if (shape.open_paths)
        c.warn(std::to_string(shape.open_paths) + " open path(s) in " + name +
               " closed by a straight edge from end to start, as OpenSCAD does");
    if (shape.loops.empty() && shape.circles.empty() && shape.segments.empty())
        return c.warn(name + (o.layer.empty() ? "" : " layer \"" + o.layer + "\"") +
                      " holds no closed outline: the empty shape");
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    if (!shape.loops.empty()) add_loops(c, shape.loops);
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
