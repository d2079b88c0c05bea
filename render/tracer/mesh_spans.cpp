// Mesh leaves (`import`, `polyhedron`): one Embree BVH per mesh over its
// triangles' boxes, in object space and shared by every leaf that uses it,
// and a leaf's spans along a ray. Embree only walks the boxes; whether the
// ray crosses a triangle is decided here, in double, by a watertight test
// whose ties are broken the same way for every triangle (docs/accuracy.md,
// "Meshes"): each crossing of a closed mesh counts exactly once, even
// through a vertex or along a shared edge, so the enter/exit parity is right.
// Pairing the crossings into spans is ours too, so nested shells and thin
// (non-solid) shells follow the CSG rules.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

// The ray in Woop, Benthin and Wald's frame ("Watertight ray/triangle
// intersection", JCGT 2013): z along the ray's largest component, x and y
// sheared so the ray is the z axis. A vertex's image depends on the vertex
// alone, so triangles sharing it see the same 2D point.
struct RayFrame {
    glm::dvec3 o;
    int kx, ky, kz;
    double sx, sy, sz;
};

struct MeshContext {
    RTCIntersectContext rtc;  // first member: Embree passes our pointer through
    SpanStack* stack;
    std::uint32_t leaf;
    RayFrame f;
};

RayFrame ray_frame(const glm::dvec3& o, const glm::dvec3& d) {
    RayFrame f;
    f.o = o;
    const glm::dvec3 a = glm::abs(d);
    f.kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
    f.kx = (f.kz + 1) % 3;
    f.ky = (f.kx + 1) % 3;
    if (d[f.kz] < 0) std::swap(f.kx, f.ky);  // keep (x, y, ray) right-handed: winding keeps its meaning
    f.sx = d[f.kx] / d[f.kz];
    f.sy = d[f.ky] / d[f.kz];
    f.sz = 1 / d[f.kz];
    return f;
}

struct P2 {
    double x, y, z;
};

P2 project(const RayFrame& f, const glm::dvec3& p) {
    const glm::dvec3 a = p - f.o;
    return {a[f.kx] - f.sx * a[f.kz], a[f.ky] - f.sy * a[f.kz], f.sz * a[f.kz]};
}

// The sign of p.x·q.y − p.y·q.x (the ray's side of the edge p→q), exact for
// the given doubles: the plain product when its error bound allows, else
// both products split exactly with fma (round-to-nearest is monotonic, so
// unequal rounded products order like the exact ones). A zero, the ray
// exactly on the edge's line, is broken as if the ray sat at (ε, ε²): the
// same rule for both triangles of an edge (p→q in one is q→p in the other,
// and the sign flips exactly), and one consistent point for all triangles
// round a vertex. 0 only when p = q: the triangle is edge-on to the ray.
int edge_sign(const P2& p, const P2& q) {
    const double ab = p.x * q.y, cd = p.y * q.x, e = ab - cd;
    if (std::abs(e) > 1e-15 * (std::abs(ab) + std::abs(cd))) return e > 0 ? 1 : -1;
    if (ab != cd) return ab > cd ? 1 : -1;
    const double lo = std::fma(p.x, q.y, -ab) - std::fma(p.y, q.x, -cd);
    if (lo != 0) return lo > 0 ? 1 : -1;
    if (p.y != q.y) return p.y > q.y ? 1 : -1;
    if (p.x != q.x) return q.x > p.x ? 1 : -1;
    return 0;
}

// t where the ray meets a triangle seen (nearly) edge-on, whose barycentric
// weights are round-off: the point of its 2D outline nearest the ray, on an
// edge, so the span end stays on the surface (a ray grazing a face).
double edge_on_t(const P2& a, const P2& b, const P2& c) {
    const P2* v[3] = {&a, &b, &c};
    double best = kInf, t = (a.z + b.z + c.z) / 3;
    for (int k = 0; k < 3; ++k) {
        const P2& p = *v[k];
        const P2& q = *v[(k + 1) % 3];
        const double ex = q.x - p.x, ey = q.y - p.y, len2 = ex * ex + ey * ey;
        const double l = len2 > 0 ? std::clamp(-(p.x * ex + p.y * ey) / len2, 0.0, 1.0) : 0.0;
        const double x = p.x + l * ex, y = p.y + l * ey, dist2 = x * x + y * y;
        if (dist2 < best) best = dist2, t = p.z + l * (q.z - p.z);
    }
    return t;
}

// Embree's bounds for triangle i: its box, rounded out to float and padded
// for the float ray Embree walks with (within ~1e-7 of ours; `pad` is
// 1e-6 of the mesh's size and distance from the origin).
void mesh_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* mesh = static_cast<const csg::Mesh*>(args->geometryUserPtr);
    const std::uint32_t* tri = &mesh->triangles[std::size_t(args->primID) * 3];
    const std::size_t n = mesh->points.size();
    glm::dvec3 lo(kInf), hi(-kInf);
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3& p = mesh->points[tri[k] < n ? tri[k] : 0];  // lowering validates; stay in range
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double pad = mesh->points.empty() ? 0 : 1e-6 * (glm::length(hi - lo) + glm::length(glm::abs(lo) + glm::abs(hi)));
    RTCBounds* b = args->bounds_o;
    b->lower_x = round_down(lo.x - pad), b->lower_y = round_down(lo.y - pad), b->lower_z = round_down(lo.z - pad);
    b->upper_x = round_up(hi.x + pad), b->upper_y = round_up(hi.y + pad), b->upper_z = round_up(hi.z + pad);
}

// Records a crossing of triangle primID (t, entering or leaving) and never
// reports a hit, so Embree goes on to every other box the ray meets.
void mesh_intersect(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<MeshContext*>(args->context);
    const auto* mesh = static_cast<const csg::Mesh*>(args->geometryUserPtr);
    const std::uint32_t* tri = &mesh->triangles[std::size_t(args->primID) * 3];
    const std::size_t n = mesh->points.size();
    const P2 a = project(ctx->f, mesh->points[tri[0] < n ? tri[0] : 0]);
    const P2 b = project(ctx->f, mesh->points[tri[1] < n ? tri[1] : 0]);
    const P2 c = project(ctx->f, mesh->points[tri[2] < n ? tri[2] : 0]);
    const int su = edge_sign(b, c), sv = edge_sign(c, a), sw = edge_sign(a, b);
    if (su == 0 || su != sv || su != sw) return;
    // Inside all three edges: the ray crosses. Counter-clockwise seen along
    // the ray means the outward normal points along it: leaving.
    const double u = b.x * c.y - b.y * c.x, v = c.x * a.y - c.y * a.x, w = a.x * b.y - a.y * b.x;
    const double det = u + v + w;
    const double mag = std::abs(b.x * c.y) + std::abs(b.y * c.x) + std::abs(c.x * a.y) + std::abs(c.y * a.x) +
                       std::abs(a.x * b.y) + std::abs(a.y * b.x);
    const double t = std::abs(det) > 1e-8 * mag ? (u * a.z + v * b.z + w * c.z) / det : edge_on_t(a, b, c);
    Span s;
    s.t0 = s.t1 = t;
    s.e0 = SpanEnd{ctx->leaf, ctx->leaf, std::uint8_t(su < 0 ? 1 : 0), 0, 0, args->primID};  // part 1: entering
    s.e1 = s.e0;
    s.inner = ctx->leaf;
    ctx->stack->push(s);
}

// The object-space ray o + t·d on the mesh's box, padded: false if it misses.
bool box_chord(const csg::Aabb& box, const glm::dvec3& o, const glm::dvec3& d, double& t0, double& t1) {
    t0 = -kInf, t1 = kInf;
    const double pad = 1e-6 * (glm::length(box.hi - box.lo) + 1e-300);
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0) {
            if (o[i] < box.lo[i] - pad || o[i] > box.hi[i] + pad) return false;
            continue;
        }
        double ta = (box.lo[i] - pad - o[i]) / d[i], tb = (box.hi[i] + pad - o[i]) / d[i];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 < t1;
}

// Crossing i repeats crossing i - 1 (same direction, t a rounding apart):
// a thin shell's sheets that close make one sliver, not two.
bool repeats(const Span* h, std::uint32_t i, double same) {
    return i > 0 && h[i - 1].e0.part == h[i].e0.part && h[i].t0 - h[i - 1].t0 <= same;
}

// A thin shell has no inside: each crossing becomes a sliver just thicker
// than the degenerate rule drops, whose entry faces the ray. Rewrites the
// sorted crossings h in place; returns the span count.
std::uint32_t shell_slivers(Span* h, std::uint32_t hits, double same, double eps, double a, double b) {
    std::uint32_t out = 0;
    for (std::uint32_t i = 0; i < hits; ++i) {
        if (repeats(h, i, same)) continue;
        Span x = h[i];
        x.e0.flip = x.e0.part == 1 ? 0 : 1;
        x.e1 = x.e0;
        x.e1.flip ^= 1;
        x.t1 = x.t0 + 4 * eps;
        if (x.t1 < a || x.t0 > b) continue;
        if (out > 0 && x.t0 <= h[out - 1].t1) {
            h[out - 1].t1 = x.t1;
            h[out - 1].e1 = x.e1;
        } else {
            h[out++] = x;
        }
    }
    return out;
}

// A solid: entering raises the depth, leaving lowers it (robust to nested
// shells); a span runs from depth 0→1 to depth 1→0. Each crossing counts
// once, so no duplicates are merged; the depth may dip below 0 where a ray
// grazes a vertex and the leaving crossing sorts first (equal t). Rewrites
// the sorted crossings h in place; returns the span count.
std::uint32_t solid_spans(Span* h, std::uint32_t hits, double eps, double a, double b) {
    std::uint32_t out = 0;
    int depth = 0;
    Span cur{};
    for (std::uint32_t i = 0; i < hits; ++i) {
        const Span x = h[i];
        if (x.e0.part == 1) {  // entering
            if (depth++ == 0) cur = x;
        } else if (--depth == 0) {
            cur.t1 = x.t0;
            cur.e1 = x.e0;
            if (cur.t1 - cur.t0 > eps && cur.t1 >= a && cur.t0 <= b) h[out++] = cur;
        }
    }
    return out;
}

}  // namespace

void CsgTracer::Impl::build_meshes() {
    mesh_bvhs.assign(scene.meshes.size(), nullptr);
    mesh_boxes.assign(scene.meshes.size(), csg::Aabb{});
    if (scene.meshes.empty()) return;  // (no pass over 10^5 leaves for nothing)
    for (const csg::Leaf& leaf : scene.leaves) {
        if (leaf.kind != csg::PrimKind::Mesh || leaf.mesh >= scene.meshes.size() || mesh_bvhs[leaf.mesh]) continue;
        const csg::Mesh& mesh = scene.meshes[leaf.mesh];
        if (mesh.points.empty() || mesh.triangles.size() < 3) continue;  // an empty mesh is an empty solid
        // Every handle and buffer is checked: out of memory, Embree returns
        // null (writing through it crashed); the Impl releases what is stored.
        RTCScene ms = rtcNewScene(device);
        if (!ms) embree_failed(device, "a mesh");
        mesh_bvhs[leaf.mesh] = ms;
        rtcSetSceneFlags(ms, RTC_SCENE_FLAG_ROBUST);
        // A user geometry over the triangles' boxes: the crossing test is ours
        // (mesh_intersect), in double on the mesh's own points.
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        if (!g) embree_failed(device, "a mesh");
        rtcSetGeometryUserPrimitiveCount(g, unsigned(mesh.triangles.size() / 3));
        rtcSetGeometryUserData(g, const_cast<csg::Mesh*>(&mesh));
        rtcSetGeometryBoundsFunction(g, mesh_bounds, nullptr);
        rtcSetGeometryIntersectFunction(g, mesh_intersect);
        rtcCommitGeometry(g);
        rtcAttachGeometry(ms, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(ms);
        check_embree(device, "a mesh");
        csg::Aabb box;
        for (const glm::dvec3& p : mesh.points) box.extend(p);
        mesh_boxes[leaf.mesh] = box;
    }
}

// A mesh's spans along the whole chord of its box (so a window starting
// inside the mesh still knows it is inside): all crossings, sorted, then
// paired as a solid or a thin shell.
std::uint32_t RayState::mesh_spans(std::uint32_t leaf_id, double a, double b) {
    const csg::Leaf& leaf = impl->scene.leaves[leaf_id];
    if (leaf.mesh >= impl->mesh_bvhs.size() || !impl->mesh_bvhs[leaf.mesh]) return 0;
    const glm::dvec3 lo = leaf.object_from_world.point(o);
    const glm::dvec3 ld = leaf.object_from_world.vector(d);
    double t0, t1;
    if (!box_chord(impl->mesh_boxes[leaf.mesh], lo, ld, t0, t1) || t1 < a || t0 > b) return 0;
    SpanStack& st = scratch->stack;
    const std::uint32_t base = st.size();
    MeshContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.stack = &st;
    ctx.leaf = leaf_id;
    ctx.f = ray_frame(lo, ld);
    // Embree walks a float copy of the ray from the chord's start; the boxes
    // are padded for the difference. Crossings are measured from lo in double.
    const glm::dvec3 start = lo + t0 * ld;
    RTCRayHit rh = embree_ray(float(start.x), float(start.y), float(start.z), float(ld.x), float(ld.y), float(ld.z),
                              0, round_up(1.000001 * (t1 - t0)));
    rtcIntersect1(impl->mesh_bvhs[leaf.mesh], &ctx.rtc, &rh);
    const std::uint32_t hits = st.size() - base;
    scratch->counters.interval_tests++;
    Span* h = st.at(base);
    std::sort(h, h + hits, [](const Span& x, const Span& y) { return x.t0 < y.t0; });
    const double same = 1e-6 * (t1 - t0);
    const std::uint32_t out = impl->scene.meshes[leaf.mesh].solid ? solid_spans(h, hits, eps, a, b)
                                                                  : shell_slivers(h, hits, same, eps, a, b);
    st.resize(base + out);
    scratch->counters.spans_found += out;
    return out;
}

}  // namespace kerf::render

