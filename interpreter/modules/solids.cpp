// Primitive solids (docs/spec.md §4), validated and canonicalised as the
// csg::PrimKind comments in csg/scene.hpp say.
#include <cmath>
#include <initializer_list>
#include <strings.h>

#include "interpreter/import/mesh_import.hpp"
#include "interpreter/modules/import2d.hpp"
#include "interpreter/modules/args.hpp"
#include "interpreter/modules/facets.hpp"
#include "interpreter/modules/mesh_check.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/modules/revolve_facets.hpp"

namespace kerf::eval {

namespace {

// r or d (d/2); both is an error. Returns fallback when neither is given.
std::optional<double> radius(const Args& a, std::size_t ri, std::size_t di, const char* rn, const char* dn) {
    if (a.has(ri) && a.has(di)) arg_error(a, std::string("give ") + rn + " or " + dn + ", not both");
    if (a.has(ri)) return arg_number(a, ri, rn, 0);
    if (a.has(di)) return arg_number(a, di, dn, 0) / 2;
    return std::nullopt;
}

using P = csg::PrimKind;

// Orients a solid mesh (mesh_check.hpp) and says what it changed; an open,
// non-manifold or non-orientable one has no inside and becomes a thin shell.
void orient(ModuleCall& c, graph::PolygonMesh& mesh) {
    if (!mesh.solid) return;  // a shell by request: its faces need no inside
    const MeshCheck m = check_mesh(mesh);
    if (m.faces_turned == m.faces)
        c.warn("all " + std::to_string(m.faces) +
               " faces were wound inside out and have been reversed (faces go clockwise seen from outside)");
    else if (m.faces_turned > 0)
        c.warn(std::to_string(m.faces_turned) + " of " + std::to_string(m.faces) +
               (m.faces_turned == 1 ? " faces was" : " faces were") + " wound against their neighbours and turned round");
    if (m.closed()) return;
    std::string why;
    if (m.open_edges) why = std::to_string(m.open_edges) + (m.open_edges == 1 ? " edge belongs" : " edges belong") + " to one face only";
    if (m.nonmanifold_edges)
        why += (why.empty() ? "" : ", ") + std::to_string(m.nonmanifold_edges) +
               (m.nonmanifold_edges == 1 ? " edge is" : " edges are") + " shared by more than two faces";
    if (m.nonorientable) why += std::string(why.empty() ? "" : ", ") + "its faces cannot be oriented consistently";
    c.warn("the mesh is not a closed solid (" + why + "): it is rendered as a thin shell");
    mesh.solid = false;
}

void sphere(ModuleCall& c) {
    const Args& a = c.args;
    double r = radius(a, 0, 1, "r", "d").value_or(1);
    if (!(r > 0)) arg_error(a, "radius must be positive, got " + format_number(r));
    if (c.facet_mode() == FacetMode::OpenScad) return add_openscad_sphere(c, honoured_facets(c, r), r);
    if (honoured_facets(c))  // auto builds no rings of facets: say so, the sphere is round
        c.warn("$fn = " + format_number(c.args.fn) + " is not honoured on a sphere; the sphere is exact");
    else c.exact_curve();
    c.add_primitive(P::Sphere, {r});
}

void cube(ModuleCall& c) {
    const Args& a = c.args;
    glm::dvec3 size(1);
    if (a.has(0) && a[0].is_number()) size = glm::dvec3(arg_number(a, 0, "size", 1));
    else size = arg_vec3(a, 0, "size", size);
    for (int k = 0; k < 3; ++k)
        if (!(size[k] > 0)) arg_error(a, "size must be positive, got " + format_number(size[k]));
    bool center = arg_bool(a, 1, "center", false);
    glm::dvec3 lo = center ? -size / 2.0 : glm::dvec3(0);
    glm::dvec3 hi = center ? size / 2.0 : size;
    c.add_primitive(P::Box, {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
}

void frustum(ModuleCall& c, double h, double r1, double r2, bool center) {
    double z0 = center ? -h / 2 : 0;
    c.add_primitive(P::Cylinder, {z0, z0 + h, r1, r2});
}

// OpenSCAD's n-sided prism, frustum or pyramid: the n-gon of the larger
// radius extruded and tapered to the other (to a point for a cone's tip),
// upside down when the larger radius is on top.
void faceted_frustum(ModuleCall& c, int n, double h, double r1, double r2, bool center) {
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    const bool flip = r2 > r1;
    add_regular_prism(c, n, flip ? r2 : r1, (flip ? r1 / r2 : r2 / r1) - 1);
    const double z0 = center ? -h / 2 : 0;
    if (flip) g.extrude(mark, z0 + h, z0, c.st.loc);
    else g.extrude(mark, z0, z0 + h, c.st.loc);
}

// In the OpenSCAD dialect, a cylinder given both takes what OpenSCAD 2021
// takes, with its warnings: d over r (and d1 over r1, d2 over r2), then
// r1/r2 over r (docs/openscad.md "Built-in modules").
std::optional<double> openscad_radius(ModuleCall& c, std::size_t ri, std::size_t di, const char* rn, const char* dn) {
    const Args& a = c.args;
    if (!c.lenient() || !a.has(ri) || !a.has(di)) return radius(a, ri, di, rn, dn);
    c.warn(std::string("Ignoring radius variable '") + rn + "' as diameter '" + dn + "' is defined too.");
    return arg_number(a, di, dn, 0) / 2;
}

void cylinder(ModuleCall& c) {
    const Args& a = c.args;
    double h = arg_positive(a, 0, "h", 1);
    auto general = openscad_radius(c, 4, 5, "r", "d");
    auto end1 = openscad_radius(c, 1, 6, "r1", "d1");
    auto end2 = openscad_radius(c, 2, 7, "r2", "d2");
    if (general && (end1 || end2)) {
        if (!c.lenient()) arg_error(a, "give r/d or r1/r2/d1/d2, not both");
        c.warn("Cylinder parameters ambiguous");
    }
    double r1 = end1.value_or(general.value_or(1));
    double r2 = end2.value_or(general.value_or(1));
    bool center = arg_bool(a, 3, "center", false);
    if (r1 < 0 || r2 < 0) arg_error(a, "radius must not be negative, got " + format_number(std::min(r1, r2)));
    if (r1 == 0 && r2 == 0) arg_error(a, "radius must be positive, got 0");
    const int n = honoured_facets(c, std::max(r1, r2));
    if (n && ((r1 > 0 && r2 > 0) || c.facet_mode() == FacetMode::OpenScad)) return faceted_frustum(c, n, h, r1, r2, center);
    if (n) c.warn("$fn = " + format_number(c.args.fn) + " is not honoured on a cone's tip; the cone is exact");
    else c.exact_curve();
    frustum(c, h, r1, r2, center);
}

void cone(ModuleCall& c) {
    const Args& a = c.args;
    double h = arg_positive(a, 0, "h", 1);
    double r = radius(a, 1, 3, "r", "d").value_or(1);
    if (!(r > 0)) arg_error(a, "radius must be positive, got " + format_number(r));
    const bool center = arg_bool(a, 2, "center", false);
    // --facets openscad: OpenSCAD's cylinder(h, r, 0); otherwise exact (a $fn on it is ignored too).
    if (c.facet_mode() == FacetMode::OpenScad) return faceted_frustum(c, honoured_facets(c, r), h, r, 0, center);
    c.exact_curve();
    frustum(c, h, r, 0, center);
}

void torus(ModuleCall& c) {
    const Args& a = c.args;
    double R = arg_positive(a, 0, "R", 1);
    double r = arg_positive(a, 1, "r", 0.25);
    if (!(r < R))
        arg_error(a, "minor radius r must be smaller than R, got r = " + format_number(r) + ", R = " + format_number(R));
    // --facets openscad: as OpenSCAD's rotate_extrude() translate([R, 0]) circle(r).
    if (c.facet_mode() == FacetMode::OpenScad) return faceted_torus(c, R, r);
    c.exact_curve();
    c.add_primitive(P::Torus, {R, r});
}

void plane(ModuleCall& c) {
    const Args& a = c.args;
    glm::dvec3 n = arg_vec3(a, 0, "normal", {0, 0, 1});
    double offset = arg_number(a, 1, "offset", 0);
    double len = glm::length(n);
    if (!(len > 0) || !std::isfinite(len)) arg_error(a, "normal must not be zero");
    n /= len;
    c.add_primitive(P::Plane, {n.x, n.y, n.z, offset / len});
}

void paraboloid(ModuleCall& c) {
    const Args& a = c.args;
    double h = arg_positive(a, 0, "h", 1);
    double r = arg_positive(a, 1, "r", 1);
    c.exact_curve();
    c.add_primitive(P::Paraboloid, {h, r});
}

void hyperboloid(ModuleCall& c) {
    const Args& a = c.args;
    double h = arg_positive(a, 0, "h", 1);
    double r = arg_positive(a, 1, "r", 1);
    double w = arg_positive(a, 2, "waist", 0.5);
    if (!(w < r))
        arg_error(a, "waist must be smaller than r, got waist = " + format_number(w) + ", r = " + format_number(r));
    c.exact_curve();
    c.add_primitive(P::Hyperboloid, {h, r, w});
}

void polyhedron(ModuleCall& c) {
    const Args& a = c.args;
    if (!a.has(0) || !a[0].is_list()) arg_error(a, "points must be a list of [x, y, z] points");
    // OpenSCAD's deprecated name for faces, accepted in the OpenSCAD dialect
    // with OpenSCAD's warning.
    if (a.has(3) && !c.lenient()) arg_error(a, "unknown argument 'triangles'");
    const std::size_t faces_at = !a.has(1) && a.has(3) ? 3 : 1;
    if (faces_at == 3)
        c.warn("polyhedron(triangles=[]) will be removed in future releases. Use polyhedron(faces=[]) instead.");
    if (!a.has(faces_at) || !a[faces_at].is_list()) arg_error(a, "faces must be a list of point index lists");
    graph::PolygonMesh mesh;
    for (const Value& p : a[0].as_list()) {
        if (!p.is_vector(3)) arg_error(a, "points must be a list of [x, y, z] points, got an element " + to_repr(p));
        glm::dvec3 q(p.as_list()[0].as_number(), p.as_list()[1].as_number(), p.as_list()[2].as_number());
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
            arg_error(a, "points must be finite, got " + to_repr(p));
        mesh.points.push_back(q);
    }
    if (mesh.points.size() < 4) arg_error(a, "needs at least 4 points, got " + std::to_string(mesh.points.size()));
    std::size_t fi = 0;
    for (const Value& f : a[faces_at].as_list()) {
        if (!f.is_vector() || f.as_list().size() < 3)
            arg_error(a, "face " + std::to_string(fi) + " must be a list of at least 3 point indices");
        std::vector<std::uint32_t> face;
        for (const Value& idx : f.as_list()) {
            double d = idx.as_number();
            if (d != std::floor(d) || d < 0 || d >= static_cast<double>(mesh.points.size()))
                arg_error(a, "face " + std::to_string(fi) + " refers to point " + format_number(d) + " (there are " +
                                 std::to_string(mesh.points.size()) + " points)");
            face.push_back(static_cast<std::uint32_t>(d));
        }
        mesh.faces.push_back(std::move(face));
        ++fi;
    }
    if (mesh.faces.size() < 4) arg_error(a, "needs at least 4 faces, got " + std::to_string(mesh.faces.size()));
    orient(c, mesh);
    c.add_primitive(P::Mesh, {}, c.add_mesh(std::move(mesh)));
}

// A mesh file's parts (one, or an AMF's objects, a 3MF's build items),
// read once per run: their mesh indices. A broken file is an error at the
// import in .sdl; in .scad it makes nothing, with the reason as a warning,
// as OpenSCAD imports nothing from a file it cannot read. Limits stay errors.
std::vector<std::uint32_t> read_mesh_file(ModuleCall& c, const std::string& path, bool solid) {
    const std::string name = "\"" + c.args[0].as_string() + "\"";
    ImportedMesh read;
    try {
        read = import_mesh(path, {c.limits().list_elements, c.lenient()});
    } catch (const MeshLimitError& e) {
        throw SourceError(c.st.loc, "import(" + name + "): " + e.what());
    } catch (const MeshFormatError& e) {
        if (!c.lenient()) throw SourceError(c.st.loc, "import(" + name + "): " + e.what());
        c.warn(name + ": " + e.what() + ": nothing is made, as OpenSCAD imports nothing from a file it cannot read");
        return {};
    }
    for (const std::string& w : read.warnings) c.warn(name + (w.rfind("line ", 0) == 0 ? " " : ": ") + w);
    std::vector<std::uint32_t> meshes;
    for (graph::PolygonMesh& mesh : read.parts) {
        mesh.solid = solid;
        orient(c, mesh);
        meshes.push_back(c.add_mesh(std::move(mesh)));
    }
    return meshes;
}

// import()'s arguments a format does not read (neither does OpenSCAD
// 2021.01, silently): each one given warns. Indices into import()'s list.
void warn_unread(ModuleCall& c, std::initializer_list<std::size_t> unread, const char* readers) {
    static constexpr const char* kNames[] = {"file", "solid", "convexity", "layer", "origin", "scale", "center", "dpi"};
    const Args& a = c.args;
    for (std::size_t i : unread)
        if (a.has(i) && !a[i].is_undef())
            c.warn(std::string(kNames[i]) + " is ignored: it applies to " + readers + ", not to \"" + a[0].as_string() +
                   "\"");
}

void import_file(ModuleCall& c) {
    const Args& a = c.args;
    if (!a.has(0) || !a[0].is_string())
        arg_error(a, "file must be a string naming an .stl, .obj, .ply, .off, .amf, .3mf, .dxf or .svg file");
    const bool solid = arg_bool(a, 1, "solid", true);
    const std::string path = c.files().resolve_data(a[0].as_string(), c.st.loc);
    enum { Layer = 3, Origin, Scale, Center, Dpi };
    if (path.size() >= 4 && strcasecmp(path.c_str() + path.size() - 4, ".dxf") == 0) {
        warn_unread(c, {Center, Dpi}, "SVG files");
        return import_drawing(c, path);
    }
    if (path.size() >= 4 && strcasecmp(path.c_str() + path.size() - 4, ".svg") == 0) {
        warn_unread(c, {Layer, Origin, Scale}, "DXF files");
        return import_svg_drawing(c, path);
    }
    warn_unread(c, {Layer, Origin, Scale}, "DXF files");
    warn_unread(c, {Center, Dpi}, "SVG files");
    const std::string key = (solid ? "1|" : "0|") + path;
    auto it = c.state().imported_parts.find(key);
    if (it == c.state().imported_parts.end()) it = c.state().imported_parts.emplace(key, read_mesh_file(c, path, solid)).first;
    // Several parts are united, as OpenSCAD unites an AMF's objects.
    const std::size_t mark = c.graph().mark();
    for (std::uint32_t mesh : it->second) c.add_primitive(P::Mesh, {}, mesh);
    c.graph().group(mark, c.st.loc);
}

const ModuleEntry kSolids[] = {
    {"sphere", ModuleKind::Solid, {"r", "d"}, sphere},
    {"cube", ModuleKind::Solid, {"size", "center"}, cube},
    {"cylinder", ModuleKind::Solid, {"h", "r1", "r2", "center", "r", "d", "d1", "d2"}, cylinder},
    {"cone", ModuleKind::Solid, {"h", "r", "center", "d"}, cone},
    {"torus", ModuleKind::Solid, {"R", "r"}, torus},
    {"plane", ModuleKind::Solid, {"normal", "offset"}, plane},
    {"paraboloid", ModuleKind::Solid, {"h", "r"}, paraboloid},
    {"hyperboloid", ModuleKind::Solid, {"h", "r", "waist"}, hyperboloid},
    {"polyhedron", ModuleKind::Solid, {"points", "faces", "convexity", "triangles"}, polyhedron},
    {"import", ModuleKind::Solid, {"file", "solid", "convexity", "layer", "origin", "scale", "center", "dpi"}, import_file},
};

}  // namespace

std::span<const ModuleEntry> solid_modules() { return kSolids; }

}  // namespace kerf::eval
