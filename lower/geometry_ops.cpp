#include "lower/geometry_ops.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "lower/convex_hull.hpp"
#include "lower/convex_solid.hpp"
#include "lower/flat_tree.hpp"
#include "lower/hull_points.hpp"

namespace kerf {

namespace {

using graph::NodeKind;

// Sizes past which a Minkowski sum is refused rather than built slowly
// (docs/lowering.md): pieces multiply, and so do their points.
constexpr std::size_t kMaxPieces = 4096;
constexpr std::size_t kMaxSumPoints = 4'000'000;

class Resolver {
public:
    Resolver(const graph::SceneGraph& g, graph::SceneGraph& out) : g_(g), out_(out), add_(out) {}

    void run() {
        out_.matrices = g_.matrices;
        out_.materials = g_.materials;
        copy_used_meshes();
        out_.polygons = g_.polygons;
        out_.camera = g_.camera;
        out_.lights = g_.lights;
        out_.background = g_.background;
        out_.ambient_occlusion = g_.ambient_occlusion;
        out_.fog = g_.fog;
        map_.resize(g_.nodes.size());
        for (std::uint32_t i = 0; i < g_.nodes.size(); ++i) {
            const graph::Node& n = g_.nodes[i];
            std::vector<std::uint32_t> kids;
            for (std::uint32_t k = 0; k < n.child_count; ++k) {
                const std::size_t ref = std::size_t(n.first_child) + k;
                if (ref >= g_.child_refs.size() || g_.child_refs[ref] >= i)
                    throw std::invalid_argument("lower_to_csg: malformed scene graph (bad child reference)");
                kids.push_back(map_[g_.child_refs[ref]]);
            }
            if (n.kind == NodeKind::Hull) map_[i] = hull(n, kids);
            else if (n.kind == NodeKind::Minkowski) map_[i] = minkowski(n, kids);
            else if (n.kind == NodeKind::Resize) map_[i] = resize(n, kids);
            else {
                graph::Node copy = n;
                copy.first_child = std::uint32_t(out_.child_refs.size());
                out_.child_refs.insert(out_.child_refs.end(), kids.begin(), kids.end());
                map_[i] = add_.add(std::move(copy));
            }
        }
        out_.root = g_.root < map_.size() ? map_[g_.root] : std::uint32_t(out_.nodes.size());
        for (int k = 0; k < 2; ++k)
            out_.ghost_roots[k] = g_.ghost_roots[k] < map_.size() ? map_[g_.ghost_roots[k]] : csg::kNone;
    }

private:
    const graph::SceneGraph& g_;
    graph::SceneGraph& out_;

    // The meshes the result still draws, copied at their indices; a mesh
    // seen only through a hull() or minkowski() (whose pieces read it from
    // g_, see pieces()) is left empty — a polyhedron of 10,000 points
    // would otherwise be copied face by face only to be dropped. Below a
    // resize() everything is kept, wherever it is: its box lowers the
    // child itself.
    void copy_used_meshes() {
        constexpr std::uint8_t kUnused = 0, kDrawn = 1, kUnderResize = 2;
        std::vector<std::uint8_t> use(g_.nodes.size(), kUnused);
        if (g_.root < use.size()) use[g_.root] = kDrawn;
        for (std::uint32_t ghosts : g_.ghost_roots)
            if (ghosts < use.size()) use[ghosts] = kDrawn;
        out_.meshes.resize(g_.meshes.size());
        for (std::size_t i = g_.nodes.size(); i-- > 0;) {  // parents after their children: walk down
            const graph::Node& n = g_.nodes[i];
            if (use[i] != kUnused && n.kind == NodeKind::Primitive && n.prim == csg::PrimKind::Mesh &&
                n.index < g_.meshes.size() && out_.meshes[n.index].points.empty())
                out_.meshes[n.index] = g_.meshes[n.index];
            const bool consumed = (n.kind == NodeKind::Hull || (n.kind == NodeKind::Minkowski && n.child_count > 1));
            const std::uint8_t down = n.kind == NodeKind::Resize ? kUnderResize
                                      : consumed && use[i] != kUnderResize ? kUnused
                                                                           : use[i];
            for (std::uint32_t k = 0; k < n.child_count; ++k) {
                const std::size_t ref = std::size_t(n.first_child) + k;
                if (ref < g_.child_refs.size() && g_.child_refs[ref] < i)
                    use[g_.child_refs[ref]] = std::max(use[g_.child_refs[ref]], down);
            }
        }
    }
    GraphAppender add_;
    std::vector<std::uint32_t> map_;
    std::unordered_map<std::uint32_t, ConvexPiece> solved_;  // a convex result's piece, for outer operations

    // The convex pieces of the subtree at `id` (in out_) under `xf`, appended
    // to `out`: union members separately; a difference by its minuend and
    // an intersection by its first operand (bigger than the solid: the
    // interpreter warns); a resolved hull by its own piece.
    void pieces(std::uint32_t id, const glm::dmat4& xf, double tol, std::vector<ConvexPiece>& out) {
        std::vector<std::pair<std::uint32_t, glm::dmat4>> todo{{id, xf}};
        while (!todo.empty()) {
            auto [at, m] = todo.back();
            todo.pop_back();
            const graph::Node& n = out_.nodes[at];
            double s = 0;
            auto it = solved_.find(at);
            if (it != solved_.end() && (it->second.radius == 0 || (it->second.disc ? planar_similarity(glm::dmat3(m), s)
                                                                                   : similarity(glm::dmat3(m), s)))) {
                ConvexPiece p = it->second;
                for (glm::dvec3& q : p.points) q = glm::dvec3(m * glm::dvec4(q, 1));
                p.radius *= s;
                out.push_back(std::move(p));
                continue;
            }
            if (n.kind == NodeKind::Primitive) {
                // The input's meshes from the input (copy_used_meshes), the hulls built here from out_.
                const bool built = n.prim == csg::PrimKind::Mesh && n.index >= g_.meshes.size();
                out.push_back(leaf_piece(built ? out_ : g_, n, m, tol));
                continue;
            }
            const glm::dmat4 inner = n.kind == NodeKind::Transform ? m * out_.matrices[n.index] : m;
            const std::uint32_t count =
                n.kind == NodeKind::Difference || n.kind == NodeKind::Intersection ? std::min(n.child_count, 1u)
                                                                                    : n.child_count;
            for (std::uint32_t k = 0; k < count; ++k) todo.push_back({out_.child_refs[n.first_child + k], inner});
        }
    }

    ConvexHull hull_of(const std::vector<glm::dvec3>& pts, const SourceLoc& loc) {
        try {
            return convex_hull(pts);
        } catch (const std::runtime_error& e) {
            throw SourceError(loc, std::string("hull: ") + e.what());
        }
    }

    // A piece reduced to its hull's corners.
    ConvexPiece reduced(ConvexPiece p, const SourceLoc& loc) {
        if (p.points.size() > 4) p.points = hull_of(p.points, loc).points;
        return p;
    }

    // The solid of a piece, remembered as that piece for outer operations.
    std::uint32_t solid(const ConvexPiece& p, const SourceLoc& loc) {
        ConvexHull h = hull_of(p.points, loc);
        ConvexPiece corners{h.points, p.radius, p.exact, p.disc};
        const std::uint32_t id = convex_solid(add_, std::move(h), p.radius, p.disc, loc);
        solved_[id] = std::move(corners);
        return id;
    }

    // A rounded piece as plain points: its corners each with a tessellated
    // ball (or disc) around them.
    ConvexPiece tessellated(const ConvexPiece& p, double tol, const SourceLoc& loc) {
        if (p.radius == 0) return p;
        std::vector<glm::dvec3> round = sphere_points(p.radius, tol);
        if (p.disc) {
            round.clear();
            const int n = circle_segments(tol);
            for (int i = 0; i < n; ++i) {
                const double a = 2 * 3.14159265358979323846 * i / n;
                round.push_back(p.radius * glm::dvec3(std::cos(a), std::sin(a), 0));
            }
        }
        ConvexPiece out{{}, 0, false, false};
        for (const glm::dvec3& c : reduced(p, loc).points)
            for (const glm::dvec3& b : round) out.points.push_back(c + b);
        return out;
    }

    std::uint32_t hull(const graph::Node& n, const std::vector<std::uint32_t>& kids) {
        std::vector<ConvexPiece> ps;
        for (std::uint32_t k : kids) pieces(k, glm::dmat4(1.0), n.p[0], ps);
        if (ps.empty()) return add_.empty(n.loc);
        // Equal radii (0 included) of one kind: the hull of the centres grown
        // by the ball or disc, exactly. Otherwise the rounding is tessellated.
        bool equal = true;
        for (const ConvexPiece& p : ps)
            equal = equal && std::abs(p.radius - ps[0].radius) <= 1e-12 * ps[0].radius && p.disc == ps[0].disc;
        ConvexPiece all;
        all.radius = equal ? ps[0].radius : 0;
        all.disc = equal && ps[0].disc;
        for (ConvexPiece& p : ps) {
            const ConvexPiece q = equal ? std::move(p) : tessellated(p, n.p[0], n.loc);
            all.points.insert(all.points.end(), q.points.begin(), q.points.end());
            all.exact = all.exact && q.exact;
        }
        return solid(all, n.loc);
    }

    std::uint32_t minkowski(const graph::Node& n, const std::vector<std::uint32_t>& kids) {
        if (kids.size() == 1) return kids[0];  // OpenSCAD: the child unchanged
        std::vector<ConvexPiece> sums{ConvexPiece{{glm::dvec3(0)}, 0, true}};
        std::size_t used = 0;
        for (std::uint32_t k : kids) {
            std::vector<ConvexPiece> ps;
            pieces(k, glm::dmat4(1.0), n.p[0], ps);
            if (ps.empty()) continue;  // an empty operand is skipped, as OpenSCAD does
            ++used;
            if (sums.size() * ps.size() > kMaxPieces)
                throw SourceError(n.loc, "minkowski: " + std::to_string(sums.size() * ps.size()) +
                                             " convex pieces, more than kerf builds (" + std::to_string(kMaxPieces) + ")");
            std::vector<ConvexPiece> next;
            for (ConvexPiece& q : ps) q = reduced(std::move(q), n.loc);
            for (const ConvexPiece& a : sums)
                for (const ConvexPiece& b : ps) {
                    if (a.points.size() * b.points.size() > kMaxSumPoints)
                        throw SourceError(n.loc, "minkowski: a sum of " + std::to_string(a.points.size()) + " and " +
                                                     std::to_string(b.points.size()) +
                                                     " points is too large; a coarser --curve-tolerance makes fewer");
                    // A ball and a disc do not add up to either: the disc is tessellated.
                    const bool clash = a.radius > 0 && b.radius > 0 && a.disc != b.disc;
                    const ConvexPiece& x = clash && a.disc ? tessellated(a, n.p[0], n.loc) : a;
                    const ConvexPiece& y = clash && b.disc ? tessellated(b, n.p[0], n.loc) : b;
                    ConvexPiece s{{}, x.radius + y.radius, x.exact && y.exact, x.radius > 0 ? x.disc : y.disc};
                    s.points.reserve(x.points.size() * y.points.size());
                    for (const glm::dvec3& u : x.points)
                        for (const glm::dvec3& v : y.points) s.points.push_back(u + v);
                    next.push_back(reduced(std::move(s), n.loc));
                }
            sums = std::move(next);
        }
        if (used == 0) return add_.empty(n.loc);
        std::vector<std::uint32_t> parts;
        for (const ConvexPiece& s : sums) parts.push_back(solid(s, n.loc));
        const std::uint32_t sum = parts.size() == 1 ? parts[0] : add_.op(NodeKind::Union, parts, n.loc);
        if (!n.flat || used == 1) return sum;
        // 2D: the sum of k unit slabs is the 2D sum times 0 < z < k; back to the unit slab.
        glm::dmat4 m(1.0);
        m[2][2] = 1.0 / double(used);
        return add_.transform(m, sum, n.loc);
    }

    // OpenSCAD 2021's resize: per axis, scale = newsize / size where newsize
    // is not 0; `auto` axes with newsize 0 take the scale of the largest
    // newsize; about the origin. A zero size along a resized axis leaves the
    // child unchanged, as OpenSCAD does.
    std::uint32_t resize(const graph::Node& n, const std::vector<std::uint32_t>& kids) {
        if (kids.empty()) return add_.empty(n.loc);
        const std::uint32_t child = kids[0];
        const std::uint32_t keep = out_.root;
        out_.root = child;
        std::vector<csg::Leaf> scratch;
        const lowering::FlatTree t = lowering::build_flat_tree(out_, scratch);
        out_.root = keep;
        if (t.root == csg::kNone) return child;
        const csg::Aabb box = lowering::box(t.nodes[t.root], scratch, t.boxes);
        const glm::dvec3 size = box.hi - box.lo;
        if (!std::isfinite(size.x) || !std::isfinite(size.y) || !std::isfinite(size.z))
            throw SourceError(n.loc, "resize: the child is unbounded (a half-space), it has no size");
        const glm::dvec3 want(n.p[0], n.p[1], n.p[2]);
        glm::dvec3 scale(1);
        int largest = 0;
        const int dims = n.flat ? 2 : 3;  // a 2D shape's slab keeps its z, as OpenSCAD's 2D resize
        for (int i = 0; i < dims; ++i) {
            if (want[i] == 0) continue;
            if (size[i] == 0) return child;
            scale[i] = want[i] / size[i];
            if (want[i] > want[largest]) largest = i;
        }
        const double autoscale = want[largest] != 0 ? want[largest] / size[largest] : 1;
        for (int i = 0; i < dims; ++i)
            if (n.p[3 + i] != 0 && want[i] == 0) scale[i] = autoscale;
        glm::dmat4 m(1.0);
        m[0][0] = scale.x, m[1][1] = scale.y, m[2][2] = scale.z;
        return add_.transform(m, child, n.loc);
    }
};

}  // namespace

bool resolve_geometry_ops(const graph::SceneGraph& g, graph::SceneGraph& out) {
    bool any = false;
    for (const graph::Node& n : g.nodes)
        any = any || n.kind == NodeKind::Hull || n.kind == NodeKind::Minkowski || n.kind == NodeKind::Resize;
    if (!any) return false;
    out = graph::SceneGraph{};
    Resolver(g, out).run();
    return true;
}

}  // namespace kerf
