// Mesh leaves (`import`, `polyhedron`): one Embree triangle scene per mesh,
// in object space and shared by every leaf that uses it, and a leaf's spans
// along a ray. Embree only finds the crossings (a filter records each one and
// rejects it); pairing them into spans is ours, so nested shells, shared
// edges and thin (non-solid) shells follow the CSG rules in double.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

struct MeshContext {
    RTCIntersectContext rtc;  // first member: Embree passes our pointer through
    SpanStack* stack;
    std::uint32_t leaf;
    double t_offset;
};

// Records every triangle crossed (t, triangle, entering or leaving) and
// rejects it, so Embree goes on to the next one.
void mesh_filter(const RTCFilterFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<MeshContext*>(args->context);
    const float t = RTCRayN_tfar(args->ray, args->N, 0);
    const unsigned prim = RTCHitN_primID(args->hit, args->N, 0);
    // Orientation from our own outward (CCW) winding, not Embree's Ng convention.
    const glm::dvec3 n = triangle_normal(*static_cast<const csg::Mesh*>(args->geometryUserPtr), prim);
    const double dn = n.x * RTCRayN_dir_x(args->ray, args->N, 0) + n.y * RTCRayN_dir_y(args->ray, args->N, 0) +
                      n.z * RTCRayN_dir_z(args->ray, args->N, 0);
    Span s;
    s.t0 = s.t1 = ctx->t_offset + double(t);
    s.e0 = SpanEnd{ctx->leaf, ctx->leaf, std::uint8_t(dn < 0 ? 1 : 0), 0, 0, prim};  // part 1: entering
    s.e1 = s.e0;
    s.inner = ctx->leaf;
    ctx->stack->push(s);
    args->valid[0] = 0;
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

// Crossing i repeats crossing i - 1: a shared edge, same direction and t.
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
// shells); a span runs from depth 0→1 to depth 1→0. Rewrites the sorted
// crossings h in place; returns the span count.
std::uint32_t solid_spans(Span* h, std::uint32_t hits, double same, double eps, double a, double b) {
    std::uint32_t out = 0;
    int depth = 0;
    Span cur{};
    for (std::uint32_t i = 0; i < hits; ++i) {
        if (repeats(h, i, same)) continue;
        const Span x = h[i];
        if (x.e0.part == 1) {  // entering
            if (depth++ == 0) cur = x;
        } else if (depth > 0 && --depth == 0) {
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
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        if (!g) embree_failed(device, "a mesh");
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), mesh.points.size()));
        const std::size_t tris = mesh.triangles.size() / 3;
        auto* idx = v ? static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(unsigned), tris))
                      : nullptr;
        if (!idx) {
            rtcReleaseGeometry(g);
            embree_failed(device, "a mesh");
        }
        csg::Aabb box;
        for (std::size_t i = 0; i < mesh.points.size(); ++i) {
            for (int c = 0; c < 3; ++c) v[3 * i + c] = float(mesh.points[i][c]);
            box.extend(mesh.points[i]);
        }
        for (std::size_t i = 0; i < 3 * tris; ++i)
            idx[i] = mesh.triangles[i] < mesh.points.size() ? mesh.triangles[i] : 0;  // lowering validates; stay in range
        rtcSetGeometryUserData(g, const_cast<csg::Mesh*>(&mesh));
        rtcSetGeometryIntersectFilterFunction(g, mesh_filter);
        rtcCommitGeometry(g);
        rtcAttachGeometry(ms, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(ms);
        check_embree(device, "a mesh");
        mesh_boxes[leaf.mesh] = box;
    }
}

// A mesh's spans along the whole chord of its box (so a window starting
// inside the mesh still knows it is inside): all crossings, sorted, edge
// duplicates merged, then paired as a solid or a thin shell.
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
    ctx.t_offset = t0;
    const glm::dvec3 start = lo + t0 * ld;
    RTCRayHit rh = embree_ray(float(start.x), float(start.y), float(start.z), float(ld.x), float(ld.y), float(ld.z),
                              0, round_up(t1 - t0));
    rtcIntersect1(impl->mesh_bvhs[leaf.mesh], &ctx.rtc, &rh);
    const std::uint32_t hits = st.size() - base;
    scratch->counters.interval_tests++;
    Span* h = st.at(base);
    std::sort(h, h + hits, [](const Span& x, const Span& y) { return x.t0 < y.t0; });
    const double same = 1e-6 * (t1 - t0);
    const std::uint32_t out = impl->scene.meshes[leaf.mesh].solid ? solid_spans(h, hits, same, eps, a, b)
                                                                  : shell_slivers(h, hits, same, eps, a, b);
    st.resize(base + out);
    scratch->counters.spans_found += out;
    return out;
}

}  // namespace kerf::render

