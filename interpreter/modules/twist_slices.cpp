#include "interpreter/modules/twist_slices.hpp"

#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "interpreter/degrees.hpp"
#include "interpreter/modules/cap_triangles.hpp"
#include "interpreter/modules/region2d.hpp"

namespace kerf::eval {

namespace {

constexpr double kGridFine = 0.00000095367431640625;  // OpenSCAD's GRID_FINE, 2^-20

// One outline of the region: its corners, and whether it bounds a hole.
struct Outline {
    std::vector<glm::dvec2> points;
    bool hole = false;
};

// The region's outlines grouped by face: each outer boundary followed by
// its holes (Clipper's tree of the region's paths).
struct Faces {
    std::vector<Outline> outlines;
    std::vector<std::size_t> first;  // where each face's outlines start; ends with outlines.size()
};

void add_face(const ClipperLib::PolyNode& outer, const Region2& r, Faces& out) {
    out.first.push_back(out.outlines.size());
    auto add = [&](const ClipperLib::Path& path, bool hole) {
        Outline o;
        o.hole = hole;
        for (const ClipperLib::IntPoint& p : path) o.points.push_back(r.point(p));
        out.outlines.push_back(std::move(o));
    };
    add(outer.Contour, false);
    for (const ClipperLib::PolyNode* hole : outer.Childs) add(hole->Contour, true);
    for (const ClipperLib::PolyNode* hole : outer.Childs)
        for (const ClipperLib::PolyNode* island : hole->Childs) add_face(*island, r, out);
}

Faces region_faces(const Region2& r) {
    ClipperLib::Clipper clip;
    clip.AddPaths(r.paths, ClipperLib::ptSubject, true);
    ClipperLib::PolyTree tree;
    clip.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    Faces f;
    for (const ClipperLib::PolyNode* outer : tree.Childs) add_face(*outer, r, f);
    f.first.push_back(f.outlines.size());
    return f;
}

// OpenSCAD's slices for a twist alone (or with an uneven scale): the
// helix of radius r over `height`, turning by `twist` degrees.
double helix_slices(double r2, double height, double twist, const FacetVars& f) {
    twist = std::abs(twist);
    const double least = std::max(std::ceil(twist / 120.0), 1.0);  // a slice never turns 180°
    if (std::sqrt(r2) < kGridFine || !std::isfinite(f.fn)) return least;
    if (f.fn > 0) return std::max(std::ceil(twist / 360.0 * f.fn), least);
    const double turn = twist * std::numbers::pi / 180, pitch = height / turn;
    const double length = turn * std::sqrt(r2 + pitch * pitch);
    return std::max(std::min(std::ceil(twist / f.fa), std::ceil(length / f.fs)), least);
}

// Length of the Archimedes spiral r = a·θ from 0 to θ.
double spiral_length(double a, double theta) {
    return 0.5 * a * (theta * std::sqrt(1 + theta * theta) + std::asinh(theta));
}

// A twist under a uniform scale k != 1: the vertex follows a conical
// helix, a piece of an Archimedes spiral lifted over `height`.
double conical_slices(double r2, double height, double twist, double k, const FacetVars& f) {
    twist = std::abs(twist);
    const double r = std::sqrt(r2);
    const double least = std::max(std::ceil(twist / 120.0), 1.0);
    if (r < kGridFine || !std::isfinite(f.fn)) return least;
    if (f.fn > 0) return std::max(std::ceil(twist * f.fn / 360), least);
    const double turn = twist * std::numbers::pi / 180;
    // The spiral through the origin (scale 0) that the vertex's path is part of.
    const double end = k > 1 ? turn * k / (k - 1) : turn / (1 - k), start = end - turn;
    const double a = r / end;
    const double flat = spiral_length(a, end) - spiral_length(a, start);
    const double length = std::sqrt(flat * flat + height * height);
    return std::max(std::min(std::ceil(twist / f.fa), std::ceil(length / f.fs)), least);
}

// An uneven scale without twist: the longest straight vertex path.
double diagonal_slices(double d2, double height, const FacetVars& f) {
    if (std::sqrt(d2) < kGridFine || !std::isfinite(f.fn)) return 1;
    if (f.fn > 0) return std::max(std::floor(f.fn), 1.0);
    return std::max(std::ceil(std::sqrt(d2 + height * height) / f.fs), 1.0);
}

// OpenSCAD's comparison of two diagonals' lengths: equal within 10 ppm of
// their mean (so a twist's mirror-symmetric quads split by a fixed rule).
int compare_lengths(glm::dvec2 u, glm::dvec2 v) {
    const double a = glm::length(u), b = glm::length(v);
    return 2 * std::abs(a - b) * 1e5 > a + b ? (a < b ? -1 : 1) : 0;
}

// A zero scale puts many corners of the top copy on one point: they are
// made one vertex, so the faces meeting there share their edges, and a
// face left with a repeated corner (of no area) is dropped.
void weld(graph::PolygonMesh& mesh) {
    std::map<std::array<double, 3>, std::uint32_t> seen;
    std::vector<std::uint32_t> to(mesh.points.size());
    for (std::size_t i = 0; i < mesh.points.size(); ++i) {
        const glm::dvec3 p = mesh.points[i];
        to[i] = seen.emplace(std::array<double, 3>{p.x, p.y, p.z}, std::uint32_t(i)).first->second;
    }
    for (auto& f : mesh.faces)
        for (std::uint32_t& v : f) v = to[v];
    std::erase_if(mesh.faces, [](const std::vector<std::uint32_t>& f) { return f[0] == f[1] || f[1] == f[2] || f[2] == f[0]; });
}

}  // namespace

double openscad_slices(const SliceSpec& s, double r2, double d2, const FacetVars& f) {
    if (s.slices >= 1) return std::floor(s.slices);  // OpenSCAD truncates; below 1 it counts its own
    if (s.twist != 0) {
        if (s.scale.x == s.scale.y && s.scale.x != 1) return conical_slices(r2, s.height, s.twist, s.scale.x, f);
        return helix_slices(r2, s.height, s.twist, f);
    }
    if (s.scale.x != s.scale.y) return diagonal_slices(d2, s.height, f);
    return 1;
}

void add_openscad_slices(ModuleCall& c, const std::vector<std::uint32_t>& shapes, const SliceSpec& s) {
    const Region2 region = flatten_region(c.graph().graph, shapes, 0, c.curve_tolerance(), c.st.loc);
    const Faces faces = region_faces(region);
    if (faces.outlines.empty()) return;
    double r2 = 0, d2 = 0;
    std::size_t corners = 0;
    for (const Outline& o : faces.outlines) {
        corners += o.points.size();
        for (glm::dvec2 p : o.points) {
            r2 = std::max(r2, glm::dot(p, p));
            const glm::dvec2 d = p - p * s.scale;
            d2 = std::max(d2, glm::dot(d, d));
        }
    }
    const double count = openscad_slices(s, r2, d2, c.facet_vars());
    // (n + 1) copies of every corner: bounded by the list limit, as a sphere's rings are.
    const double limit = std::min<double>(double(c.limits().list_elements), 1e7);
    if (!((count + 1) * double(corners) <= limit))
        throw SourceError(c.st.loc, "linear_extrude: " + format_number(count) + " slices of " + std::to_string(corners) +
                                        " corners pass the limit of " + format_number(limit) + " points (--max-list)");
    const int n = static_cast<int>(count);

    // Copy j of the outlines: scaled and turned as OpenSCAD's level j, at z = j / n.
    graph::PolygonMesh mesh;
    mesh.points.reserve(std::size_t(n + 1) * corners);
    auto scale_at = [&](int j) { return glm::dvec2(1) - (glm::dvec2(1) - s.scale) * double(j) / double(n); };
    for (int j = 0; j <= n; ++j) {
        const double turn = -s.twist * j / n, cs = cos_deg(turn), sn = sin_deg(turn);
        const glm::dvec2 k = scale_at(j);
        for (const Outline& o : faces.outlines)
            for (glm::dvec2 p : o.points)
                mesh.points.emplace_back(k.x * (cs * p.x - sn * p.y), k.y * (sn * p.x + cs * p.y), double(j) / n);
    }
    auto at = [&](int j, std::size_t i) { return static_cast<std::uint32_t>(std::size_t(j) * corners + i); };

    // The ends: the region's triangles, the bottom turned over. OpenSCAD
    // leaves the top out when a scale is 0 (it has no area); kerf keeps its
    // triangles of no area, which close the mesh edge for edge.
    std::size_t base = 0;
    for (std::size_t f = 0; f + 1 < faces.first.size(); ++f) {
        std::vector<std::vector<glm::dvec2>> rings;
        for (std::size_t k = faces.first[f]; k < faces.first[f + 1]; ++k) rings.push_back(faces.outlines[k].points);
        for (const auto& t : cap_triangles(rings)) {
            mesh.faces.push_back({at(0, base + t[0]), at(0, base + t[1]), at(0, base + t[2])});
            mesh.faces.push_back({at(n, base + t[2]), at(n, base + t[1]), at(n, base + t[0])});
        }
        for (const auto& ring : rings) base += ring.size();
    }

    // The sides, slice by slice: per edge of each outline two triangles
    // between copies j and j + 1, split along the shorter diagonal; at even
    // lengths by the twist's direction and the outline's kind (OpenSCAD's
    // rule, add_slice). Under a zero scale the split turns and a triangle
    // collapsing to nothing is left out.
    const bool back_twist = s.twist <= 0;  // OpenSCAD's: the later copy turned no further
    for (int j = 0; j < n; ++j) {
        const glm::dvec2 k2 = scale_at(j + 1);
        const bool any_zero = k2.x == 0 || k2.y == 0, any_nonzero = k2.x != 0 || k2.y != 0;
        std::size_t first = 0;
        for (const Outline& o : faces.outlines) {
            const std::size_t m = o.points.size();
            const bool flip = o.hole != back_twist;
            for (std::size_t i = 1; i <= m; ++i) {
                const std::uint32_t p1 = at(j, first + i - 1), c1 = at(j, first + i % m);
                const std::uint32_t p2 = at(j + 1, first + i - 1), c2 = at(j + 1, first + i % m);
                const glm::dvec2 P1(mesh.points[p1]), C1(mesh.points[c1]), P2(mesh.points[p2]), C2(mesh.points[c2]);
                const int diff = compare_lengths(P1 - C2, C1 - P2);
                const bool split_first = diff == -1 || (diff == 0 && !flip);
                const bool second = !any_zero || (any_nonzero && P2 != C2);
                if (split_first != any_zero) {
                    mesh.faces.push_back({p1, c2, c1});
                    if (second) mesh.faces.push_back({c2, p1, p2});
                } else {
                    mesh.faces.push_back({p1, p2, c1});
                    if (second) mesh.faces.push_back({p2, c2, c1});
                }
            }
            first += m;
        }
    }

    weld(mesh);
    // Faces clockwise seen from outside (PolygonMesh): the signed volume of
    // the faces as written is then negative; turn them all if it is not.
    double volume = 0;
    for (const auto& t : mesh.faces) {
        const glm::dvec3 a = mesh.points[t[0]], b = mesh.points[t[1]], cc = mesh.points[t[2]];
        volume += glm::dot(a, glm::cross(b, cc));
    }
    if (volume > 0)
        for (auto& t : mesh.faces) std::swap(t[0], t[2]);
    c.add_primitive(csg::PrimKind::Mesh, {}, c.add_mesh(std::move(mesh)));
}

}  // namespace kerf::eval
