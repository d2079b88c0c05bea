// The CSG tracer (README.md, "Tracer design"). Units are the operands of the
// root's union chain; the top Embree BVH finds them with closest-hit
// semantics, each unit's first entry is computed exactly by evaluating its
// subtree on a t-window, and large n-ary nodes answer "which children does
// the ray cross in [a, b]" through their own Embree BVH.
#include "render/csg_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

#include "render/primitives.hpp"

namespace kerf::render {

namespace {

using csg::Node;
using csg::Op;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kDirectChildren = 8;  // more children than this: own BVH

enum class Need : std::uint8_t {
    All,    // every span overlapping the window
    First,  // a list whose first span with t0 > a is the true first entry
    Any,    // at least one span overlapping the window, if there is one
};

float round_down(double x) {
    float f = float(x);
    return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float round_up(double x) {
    float f = float(x);
    return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

bool finite_box(const csg::Aabb& b) {
    constexpr double big = 1e30;
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(b.lo[i]) < big && std::abs(b.hi[i]) < big)) return false;
    return true;
}

void embree_error(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "kerf: embree error %d: %s\n", int(code), message ? message : "");
}

}  // namespace

struct EvalState;

// A BVH over some nodes (the root's units, or a large node's children).
struct Accel {
    const CsgTracer::Impl* impl = nullptr;
    RTCScene scene = nullptr;
    std::vector<std::uint32_t> items;  // node per Embree primID
    std::vector<RTCBounds> boxes;
    std::vector<std::uint32_t> always;  // unbounded nodes (half-spaces): tested for every ray
};

struct EvalState {
    const CsgTracer::Impl* impl;
    glm::dvec3 o, d, invd;
    float org[3], dir[3];
    double eps;       // t-length of the degenerate rule
    double box_pad;   // world-length slack of box tests
    double t_pad;     // t slack of float Embree windows
    TraceScratch* scratch;

    // `boxed`: the caller (an Embree BVH) has already found the node's box on the ray.
    std::uint32_t eval(std::uint32_t node, double a, double b, Need need, bool boxed = false);
    bool box_hit(const csg::Aabb& box, double a, double b) const;
    std::uint32_t eval_leaf(const Node& n, double a, double b);
    std::uint32_t eval_mesh(std::uint32_t leaf_id, double a, double b);
    std::uint32_t eval_union(std::uint32_t node, const Node& n, double a, double b);
    std::uint32_t eval_intersection(const Node& n, double a, double b);
    std::uint32_t eval_difference(std::uint32_t node, const Node& n, double a, double b, Need need);
    void collect(const Accel& accel, double a, double b);
    std::uint32_t first_entry_by_points(const Accel& subtrahends, std::uint32_t base, std::uint32_t i, double b);
    void collect_children(std::uint32_t node, const Node& n, std::uint32_t skip, double a, double b);
};

struct CsgTracer::Impl {
    const csg::Scene& scene;
    bool use_float;
    RTCDevice device = nullptr;
    Accel top;
    std::vector<std::int32_t> accel_of_node;  // -1: children evaluated directly
    std::vector<std::unique_ptr<Accel>> node_accels;
    std::vector<RTCScene> mesh_scenes;        // per csg::Mesh used by a leaf (object space)
    std::vector<csg::Aabb> mesh_boxes;        // object-space bounds of each mesh

    Impl(const csg::Scene& s, bool f) : scene(s), use_float(f) {}
    ~Impl() {
        if (top.scene) rtcReleaseScene(top.scene);
        for (auto& a : node_accels)
            if (a->scene) rtcReleaseScene(a->scene);
        for (RTCScene m : mesh_scenes)
            if (m) rtcReleaseScene(m);
        if (device) rtcReleaseDevice(device);
    }
    void build_accel(Accel& accel, const std::vector<std::uint32_t>& nodes, bool top_level, double scale);
    void build_meshes();
};

namespace {

struct CollectContext {
    RTCIntersectContext rtc;  // first member: Embree passes our pointer through
    EvalState* state;
    const Accel* accel;
    double a, b;
};

struct TopContext {
    RTCIntersectContext rtc;
    EvalState* state;
    const Accel* accel;
    double tnear;
    double best;              // intersect: current first entry; occluded: tfar
    std::uint32_t best_unit;
    SpanEnd best_end;
    bool found;
};

void bounds_callback(const RTCBoundsFunctionArguments* args) {
    const Accel* accel = static_cast<const Accel*>(args->geometryUserPtr);
    *args->bounds_o = accel->boxes[args->primID];
}

void collect_callback(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<CollectContext*>(args->context);
    // Never accepts: every crossed child is gathered, tfar stays.
    ctx->state->eval(ctx->accel->items[args->primID], ctx->a, ctx->b, Need::All, true);
}

// The unit's first entry in (tnear, best): closest-hit semantics, so the BVH
// culls every unit behind it.
bool try_unit_entry(TopContext& ctx, std::uint32_t unit_index, std::uint32_t node, bool boxed) {
    TraceScratch& s = *ctx.state->scratch;
    const std::uint32_t base = s.stack.size();
    const std::uint32_t n = ctx.state->eval(node, ctx.tnear, ctx.best, Need::First, boxed);
    bool better = false;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Span& sp = *s.stack.at(base + i);
        if (sp.t0 <= ctx.tnear) continue;
        if (sp.t0 < ctx.best || (sp.t0 == ctx.best && ctx.found && unit_index < ctx.best_unit)) {
            ctx.best = sp.t0;
            ctx.best_unit = unit_index;
            ctx.best_end = sp.e0;
            ctx.found = better = true;
        }
        break;
    }
    s.stack.resize(base);
    return better;
}

bool unit_blocks(TopContext& ctx, std::uint32_t node, bool boxed) {
    TraceScratch& s = *ctx.state->scratch;
    const std::uint32_t base = s.stack.size();
    const std::uint32_t n = ctx.state->eval(node, ctx.tnear, ctx.best, Need::Any, boxed);
    bool blocks = false;
    for (std::uint32_t i = 0; i < n && !blocks; ++i) {
        const Span& sp = *s.stack.at(base + i);
        blocks = std::min(sp.t1, ctx.best) - std::max(sp.t0, ctx.tnear) > ctx.state->eps;
    }
    s.stack.resize(base);
    return blocks;
}

void top_intersect_callback(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(args->context);
    if (try_unit_entry(*ctx, args->primID, ctx->accel->items[args->primID], true)) {
        RTCRayHit* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
        rh->ray.tfar = std::min(rh->ray.tfar, round_up(ctx->best) + float(ctx->state->t_pad));
        rh->hit.geomID = args->geomID;
        rh->hit.primID = args->primID;
    }
}

void top_occluded_callback(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(args->context);
    if (unit_blocks(*ctx, ctx->accel->items[args->primID], true)) {
        ctx->found = true;
        reinterpret_cast<RTCRay*>(args->ray)->tfar = -std::numeric_limits<float>::infinity();
    }
}

RTCRayHit make_rayhit(const EvalState& st, double a, double b) {
    RTCRayHit rh;
    rh.ray.org_x = st.org[0];
    rh.ray.org_y = st.org[1];
    rh.ray.org_z = st.org[2];
    rh.ray.dir_x = st.dir[0];
    rh.ray.dir_y = st.dir[1];
    rh.ray.dir_z = st.dir[2];
    rh.ray.tnear = std::max(0.0f, round_down(a) - float(st.t_pad));
    rh.ray.tfar = b == kInf ? std::numeric_limits<float>::infinity() : round_up(b) + float(st.t_pad);
    rh.ray.time = 0;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

struct MeshContext {
    RTCIntersectContext rtc;
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
    const csg::Mesh& m = *static_cast<const csg::Mesh*>(args->geometryUserPtr);
    const std::uint32_t* tri = &m.triangles[std::size_t(prim) * 3];
    const glm::dvec3 n = glm::cross(m.points[tri[1]] - m.points[tri[0]], m.points[tri[2]] - m.points[tri[0]]);
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

}  // namespace

void CsgTracer::Impl::build_meshes() {
    mesh_scenes.assign(scene.meshes.size(), nullptr);
    mesh_boxes.assign(scene.meshes.size(), csg::Aabb{});
    for (const csg::Leaf& leaf : scene.leaves) {
        if (leaf.kind != csg::PrimKind::Mesh || leaf.mesh >= scene.meshes.size() || mesh_scenes[leaf.mesh]) continue;
        const csg::Mesh& mesh = scene.meshes[leaf.mesh];
        if (mesh.points.empty() || mesh.triangles.size() < 3) continue;  // an empty mesh is an empty solid
        RTCScene ms = rtcNewScene(device);
        rtcSetSceneFlags(ms, RTC_SCENE_FLAG_ROBUST);
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), mesh.points.size()));
        csg::Aabb box;
        for (std::size_t i = 0; i < mesh.points.size(); ++i) {
            for (int c = 0; c < 3; ++c) v[3 * i + c] = float(mesh.points[i][c]);
            box.extend(mesh.points[i]);
        }
        const std::size_t tris = mesh.triangles.size() / 3;
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
        for (std::size_t i = 0; i < 3 * tris; ++i)
            idx[i] = mesh.triangles[i] < mesh.points.size() ? mesh.triangles[i] : 0;  // lowering validates; stay in range
        rtcSetGeometryUserData(g, const_cast<csg::Mesh*>(&mesh));
        rtcSetGeometryIntersectFilterFunction(g, mesh_filter);
        rtcCommitGeometry(g);
        rtcAttachGeometry(ms, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(ms);
        mesh_scenes[leaf.mesh] = ms;
        mesh_boxes[leaf.mesh] = box;
    }
    if (RTCError e = rtcGetDeviceError(device); e != RTC_ERROR_NONE)
        throw std::runtime_error("embree failed to build a mesh (error " + std::to_string(int(e)) + ")");
}

void CsgTracer::Impl::build_accel(Accel& accel, const std::vector<std::uint32_t>& nodes, bool top_level,
                                  double scale) {
    accel.impl = this;
    for (std::uint32_t node : nodes) {
        const csg::Aabb& b = scene.nodes[node].bounds;
        if (b.empty()) continue;  // an empty solid can never be hit
        if (!finite_box(b)) {
            accel.always.push_back(node);
            continue;
        }
        // Outward rounding plus slack for the float ray's own rounding.
        RTCBounds r;
        const double pad = 1e-6 * scale;
        r.lower_x = round_down(b.lo.x - pad - 1e-6 * std::abs(b.lo.x));
        r.lower_y = round_down(b.lo.y - pad - 1e-6 * std::abs(b.lo.y));
        r.lower_z = round_down(b.lo.z - pad - 1e-6 * std::abs(b.lo.z));
        r.upper_x = round_up(b.hi.x + pad + 1e-6 * std::abs(b.hi.x));
        r.upper_y = round_up(b.hi.y + pad + 1e-6 * std::abs(b.hi.y));
        r.upper_z = round_up(b.hi.z + pad + 1e-6 * std::abs(b.hi.z));
        r.align0 = r.align1 = 0;
        accel.items.push_back(node);
        accel.boxes.push_back(r);
    }
    if (accel.items.empty()) return;
    accel.scene = rtcNewScene(device);
    rtcSetSceneFlags(accel.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(accel.scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, unsigned(accel.items.size()));
    rtcSetGeometryUserData(geom, &accel);
    rtcSetGeometryBoundsFunction(geom, bounds_callback, nullptr);
    rtcSetGeometryIntersectFunction(geom, top_level ? top_intersect_callback : collect_callback);
    if (top_level) rtcSetGeometryOccludedFunction(geom, top_occluded_callback);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(accel.scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(accel.scene);
    if (RTCError e = rtcGetDeviceError(device); e != RTC_ERROR_NONE)
        throw std::runtime_error("embree failed to build the scene (error " + std::to_string(int(e)) + ")");
}

CsgTracer::CsgTracer(const csg::Scene& scene, bool use_float) : impl_(std::make_unique<Impl>(scene, use_float)) {
    // Scale: the magnitude of coordinates that matter, for relative tolerances.
    // (The camera is left out: a far camera must not coarsen the geometry's
    // tolerance; its distance enters per ray, see make_state.)
    double scale = 0;
    for (const csg::Leaf& leaf : scene.leaves)
        if (finite_box(leaf.bounds))
            scale = std::max({scale, glm::length(leaf.bounds.lo), glm::length(leaf.bounds.hi)});
    scale_ = scale > 0 ? scale : std::max(1.0, glm::length(scene.camera.position));
    eps_ = (use_float ? 2e-5 : 1e-9) * scale_;

    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device) throw std::runtime_error("cannot create the Embree device");
    rtcSetDeviceErrorFunction(impl_->device, embree_error, nullptr);

    impl_->accel_of_node.assign(scene.nodes.size(), -1);
    if (scene.root == csg::kNone) return;
    impl_->build_meshes();
    std::vector<std::uint32_t> units, stack{scene.root};
    while (!stack.empty()) {  // operands of the root's union chain, in order
        const std::uint32_t id = stack.back();
        stack.pop_back();
        const Node& n = scene.nodes[id];
        if (n.op == Op::Union) {
            for (std::uint32_t k = n.count; k-- > 0;) stack.push_back(scene.children[n.first + k]);
        } else {
            units.push_back(id);
        }
    }
    for (std::uint32_t id = 0; id < scene.nodes.size(); ++id) {
        const Node& n = scene.nodes[id];
        const std::uint32_t skip = n.op == Op::Difference ? 1 : 0;
        if ((n.op == Op::Union || n.op == Op::Difference) && n.count - skip > kDirectChildren) {
            std::vector<std::uint32_t> kids(scene.children.begin() + n.first + skip,
                                            scene.children.begin() + n.first + n.count);
            impl_->node_accels.push_back(std::make_unique<Accel>());
            impl_->build_accel(*impl_->node_accels.back(), kids, false, scale_);
            impl_->accel_of_node[id] = std::int32_t(impl_->node_accels.size() - 1);
        }
    }
    impl_->build_accel(impl_->top, units, true, scale_);
}

CsgTracer::~CsgTracer() = default;

bool EvalState::box_hit(const csg::Aabb& box, double a, double b) const {
    double t0 = a - eps, t1 = b + eps;
    for (int i = 0; i < 3; ++i) {
        const double lo = box.lo[i] - box_pad, hi = box.hi[i] + box_pad;
        if (d[i] == 0) {
            if (o[i] < lo || o[i] > hi) return false;
            continue;
        }
        double ta = (lo - o[i]) * invd[i], tb = (hi - o[i]) * invd[i];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

std::uint32_t EvalState::eval(std::uint32_t node, double a, double b, Need need, bool boxed) {
    const Node& n = impl->scene.nodes[node];
    if (!boxed && !box_hit(n.bounds, a, b)) return 0;
    switch (n.op) {
        case Op::Leaf: return eval_leaf(n, a, b);
        case Op::Union: return eval_union(node, n, a, b);
        case Op::Intersection: return eval_intersection(n, a, b);
        case Op::Difference: return eval_difference(node, n, a, b, need);
    }
    return 0;
}

std::uint32_t EvalState::eval_leaf(const Node& n, double a, double b) {
    const csg::Leaf& leaf = impl->scene.leaves[n.first];
    if (leaf.kind == csg::PrimKind::Mesh) return eval_mesh(n.first, a, b);
    const glm::dvec3 lo = leaf.object_from_world.point(o);
    const glm::dvec3 ld = leaf.object_from_world.vector(d);
    csg::Span<double> spans[csg::kMaxSpans];
    int count;
    if (impl->use_float) {
        csg::Span<float> fs[csg::kMaxSpans];
        count = csg::intersect_leaf<float>(leaf, glm::vec3(lo), glm::vec3(ld), fs);
        for (int i = 0; i < count; ++i) spans[i] = {double(fs[i].t0), double(fs[i].t1), fs[i].part0, fs[i].part1};
    } else {
        count = csg::intersect_leaf<double>(leaf, lo, ld, spans);
    }
    scratch->counters.interval_tests++;
    scratch->counters.spans_found += std::uint64_t(count);
    const std::uint32_t leaf_id = n.first;
    std::uint32_t pushed = 0;
    for (int i = 0; i < count; ++i) {
        if (spans[i].t1 < a || spans[i].t0 > b) continue;
        Span s;
        s.t0 = spans[i].t0;
        s.t1 = spans[i].t1;
        s.e0 = SpanEnd{leaf_id, leaf_id, spans[i].part0, 0, 0, 0};
        s.e1 = SpanEnd{leaf_id, leaf_id, spans[i].part1, 0, 0, 0};
        s.inner = leaf_id;
        scratch->stack.push(s);
        ++pushed;
    }
    return pushed;
}

// A mesh's spans along the whole chord of its box (so a window starting
// inside the mesh still knows it is inside): all crossings, sorted, paired
// by orientation with a depth count (robust to nested shells).
std::uint32_t EvalState::eval_mesh(std::uint32_t leaf_id, double a, double b) {
    const csg::Leaf& leaf = impl->scene.leaves[leaf_id];
    if (leaf.mesh >= impl->mesh_scenes.size() || !impl->mesh_scenes[leaf.mesh]) return 0;
    const csg::Aabb& box = impl->mesh_boxes[leaf.mesh];
    const glm::dvec3 lo = leaf.object_from_world.point(o);
    const glm::dvec3 ld = leaf.object_from_world.vector(d);
    double t0 = -kInf, t1 = kInf;
    const double pad = 1e-6 * (glm::length(box.hi - box.lo) + 1e-300);
    for (int i = 0; i < 3; ++i) {
        if (ld[i] == 0) {
            if (lo[i] < box.lo[i] - pad || lo[i] > box.hi[i] + pad) return 0;
            continue;
        }
        double ta = (box.lo[i] - pad - lo[i]) / ld[i], tb = (box.hi[i] + pad - lo[i]) / ld[i];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t0 < t1) || t1 < a || t0 > b) return 0;
    SpanStack& st = scratch->stack;
    const std::uint32_t base = st.size();
    MeshContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.stack = &st;
    ctx.leaf = leaf_id;
    ctx.t_offset = t0;
    RTCRayHit rh;
    const glm::dvec3 start = lo + t0 * ld;
    rh.ray.org_x = float(start.x), rh.ray.org_y = float(start.y), rh.ray.org_z = float(start.z);
    rh.ray.dir_x = float(ld.x), rh.ray.dir_y = float(ld.y), rh.ray.dir_z = float(ld.z);
    rh.ray.tnear = 0;
    rh.ray.tfar = round_up(t1 - t0);
    rh.ray.time = 0;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = rh.hit.primID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl->mesh_scenes[leaf.mesh], &ctx.rtc, &rh);
    const std::uint32_t hits = st.size() - base;
    scratch->counters.interval_tests++;
    Span* h = st.at(base);
    std::sort(h, h + hits, [](const Span& x, const Span& y) { return x.t0 < y.t0; });
    // Pair crossings: entering raises the depth, leaving lowers it; a
    // duplicate crossing on a shared edge (same direction, same t) counts once.
    const double same = 1e-6 * (t1 - t0);
    std::uint32_t out = 0;
    if (!impl->scene.meshes[leaf.mesh].solid) {
        // A thin shell has no inside: each crossing becomes a sliver just
        // thicker than the degenerate rule drops, whose entry faces the ray.
        for (std::uint32_t i = 0; i < hits; ++i) {
            Span x = h[i];
            if (i > 0 && h[i - 1].e0.part == x.e0.part && x.t0 - h[i - 1].t0 <= same) continue;
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
        st.resize(base + out);
        scratch->counters.spans_found += out;
        return out;
    }
    int depth = 0;
    Span cur{};
    for (std::uint32_t i = 0; i < hits; ++i) {
        const Span x = h[i];
        const bool entering = x.e0.part == 1;
        if (i > 0 && h[i - 1].e0.part == x.e0.part && x.t0 - h[i - 1].t0 <= same) continue;
        if (entering) {
            if (depth++ == 0) cur = x;
        } else if (depth > 0 && --depth == 0) {
            cur.t1 = x.t0;
            cur.e1 = x.e0;
            if (cur.t1 - cur.t0 > eps && cur.t1 >= a && cur.t0 <= b) h[out++] = cur;
        }
    }
    st.resize(base + out);
    scratch->counters.spans_found += out;
    return out;
}

void EvalState::collect(const Accel& accel, double a, double b) {
    for (std::uint32_t node : accel.always) eval(node, a, b, Need::All);
    if (!accel.scene) return;
    CollectContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.state = this;
    ctx.accel = &accel;
    ctx.a = a;
    ctx.b = b;
    RTCRayHit rh = make_rayhit(*this, a, b);
    rtcIntersect1(accel.scene, &ctx.rtc, &rh);
}

void EvalState::collect_children(std::uint32_t node, const Node& n, std::uint32_t skip, double a, double b) {
    const std::int32_t ai = impl->accel_of_node[node];
    if (ai >= 0) {
        collect(*impl->node_accels[std::size_t(ai)], a, b);
        return;
    }
    for (std::uint32_t k = skip; k < n.count; ++k) eval(impl->scene.children[n.first + k], a, b, Need::All);
}

std::uint32_t EvalState::eval_union(std::uint32_t node, const Node& n, double a, double b) {
    scratch->counters.union_ops++;
    SpanStack& st = scratch->stack;
    const std::uint32_t base = st.size();
    collect_children(node, n, 0, a, b);
    const int count = span_normalize_union(st.at(base), int(st.size() - base), eps);
    st.resize(base + std::uint32_t(count));
    return std::uint32_t(count);
}

std::uint32_t EvalState::eval_intersection(const Node& n, double a, double b) {
    scratch->counters.intersection_ops++;
    SpanStack& st = scratch->stack;
    const std::uint32_t base = st.size();
    std::uint32_t count = 0;
    for (std::uint32_t k = 0; k < n.count; ++k) {
        const std::uint32_t child = impl->scene.children[n.first + k];
        if (k == 0) {
            count = eval(child, a, b, Need::All);
        } else {
            // Later operands matter only where the running result is inside.
            const double wa = std::max(a, st.at(base)->t0);
            const double wb = std::min(b, st.at(base + count - 1)->t1);
            const std::uint32_t m = eval(child, wa, wb, Need::All);
            const std::uint32_t rbase = base + count + m;
            st.resize(rbase + count + m);
            const int r = span_intersection(st.at(base), int(count), st.at(base + count), int(m), st.at(rbase), eps);
            std::copy(st.at(rbase), st.at(rbase) + r, st.at(base));
            count = std::uint32_t(r);
        }
        st.resize(base + count);
        if (count == 0) return 0;  // an empty operand empties the intersection
    }
    return count;
}

std::uint32_t EvalState::eval_difference(std::uint32_t node, const Node& n, double a, double b, Need need) {
    scratch->counters.difference_ops++;
    SpanStack& st = scratch->stack;
    const std::uint32_t base = st.size();
    const std::uint32_t count = eval(impl->scene.children[n.first], a, b, Need::All);
    if (count == 0 || n.count == 1) return count;  // empty minuend: nothing to subtract from
    const std::uint32_t sbase = base + count;
    if (need == Need::All) {
        // Subtrahends matter only where the minuend is inside.
        collect_children(node, n, 1, std::max(a, st.at(base)->t0), std::min(b, st.at(sbase - 1)->t1));
        const int ns = span_normalize_union(st.at(sbase), int(st.size() - sbase), eps);
        const std::uint32_t rbase = sbase + std::uint32_t(ns);
        st.resize(rbase + count + std::uint32_t(ns));
        const int r = span_difference(st.at(base), int(count), st.at(sbase), ns, st.at(rbase), eps);
        std::copy(st.at(rbase), st.at(rbase) + r, st.at(base));
        st.resize(base + std::uint32_t(r));
        return std::uint32_t(r);
    }
    // First/Any: one minuend span at a time, stopping at the first piece that
    // answers the question; only that piece is returned.
    const std::int32_t ai = impl->accel_of_node[node];
    for (std::uint32_t i = 0; i < count; ++i) {
        if (need == Need::First && ai >= 0 && st.at(base + i)->t0 > a) {
            // Many subtrahends: walk from the minuend's entry with point
            // queries ("which subtrahends cover c?") instead of gathering all
            // of them along the chord, so the cost does not grow with the
            // number of holes the chord passes.
            const std::uint32_t found = first_entry_by_points(*impl->node_accels[std::size_t(ai)], base, i, b);
            if (found == 1) return 1;
            if (found == 2) break;  // beyond the window: nothing to find
            continue;
        }
        const double wa = std::max(a, st.at(base + i)->t0), wb = std::min(b, st.at(base + i)->t1);
        st.resize(sbase);
        collect_children(node, n, 1, wa, wb);
        const int ns = span_normalize_union(st.at(sbase), int(st.size() - sbase), eps);
        const std::uint32_t rbase = sbase + std::uint32_t(ns);
        st.resize(rbase + 1 + std::uint32_t(ns));
        const int r = span_difference(st.at(base + i), 1, st.at(sbase), ns, st.at(rbase), eps);
        for (int k = 0; k < r; ++k) {
            const Span piece = *st.at(rbase + std::uint32_t(k));
            const bool answers = need == Need::First
                                     ? piece.t0 > a && piece.t0 <= b
                                     : std::min(piece.t1, b) - std::max(piece.t0, a) > eps;
            if (answers) {
                *st.at(base) = piece;
                st.resize(base + 1);
                return 1;
            }
        }
    }
    st.resize(base);
    return 0;
}

// Minuend span i lies at base + i (spans after base + count are scratch).
// Returns 1 with the entry written at base, 0 if this minuend span has no
// entry, 2 if the search passed the window's end.
//
// Spans gathered on a window are only true inside it (a composite
// subtrahend's far end may still be uncut), so only crossings strictly
// inside the current window [c, end] are trusted. The window starts as the
// point c (most rays: "is the minuend's entry covered?"), then grows to the
// covering spans' claimed exit, then doubles, until it decides.
std::uint32_t EvalState::first_entry_by_points(const Accel& subtrahends, std::uint32_t base, std::uint32_t i,
                                               double b) {
    SpanStack& st = scratch->stack;
    const std::uint32_t sbase = st.size();
    const Span rest = *st.at(base + i);
    const double c = rest.t0;
    const double stop = std::min(b, rest.t1) + 2 * eps;  // nothing past this matters
    double end = c + 2 * eps;
    for (;;) {
        st.resize(sbase);
        collect(subtrahends, c - 2 * eps, end);
        const int ns = span_normalize_union(st.at(sbase), int(st.size() - sbase), eps);
        double claimed = end;  // where the gathered spans say coverage from c ends
        for (int k = 0; k < ns; ++k) claimed = std::max(claimed, st.at(sbase + std::uint32_t(k))->t1);
        const std::uint32_t rbase = sbase + std::uint32_t(ns);
        st.resize(rbase + 1 + std::uint32_t(ns));
        const int r = span_difference(&rest, 1, st.at(sbase), ns, st.at(rbase), eps);
        if (r > 0 && (st.at(rbase)->t0 == c || st.at(rbase)->t0 < end - eps)) {
            const Span piece = *st.at(rbase);
            st.resize(sbase);
            if (piece.t0 > b) return 2;
            *st.at(base) = piece;
            st.resize(base + 1);
            return 1;
        }
        if (end >= stop) {  // the window covered everything that matters: no entry
            st.resize(sbase);
            return rest.t1 + 2 * eps > stop ? 2 : 0;
        }
        end = std::min(stop, std::max(claimed + 2 * eps, c + 2 * (end - c)));
    }
}

namespace {

EvalState make_state(const CsgTracer::Impl* impl, const TraceRay& ray, double eps_world, double scale,
                     TraceScratch& scratch) {
    EvalState st;
    st.impl = impl;
    st.o = ray.o;
    st.d = ray.d;
    for (int i = 0; i < 3; ++i) {
        st.invd[i] = ray.d[i] != 0 ? 1.0 / ray.d[i] : kInf;
        st.org[i] = float(ray.o[i]);
        st.dir[i] = float(ray.d[i]);
    }
    const double len = glm::length(ray.d);
    // Round-off of t also grows with the origin's distance (far cameras).
    st.eps = (eps_world + (impl->use_float ? 1e-6 : 1e-13) * glm::length(ray.o)) / len;
    st.box_pad = eps_world;
    st.t_pad = 1e-5 * (scale + glm::length(ray.o)) / len;
    st.scratch = &scratch;
    return st;
}

}  // namespace

bool CsgTracer::intersect(const TraceRay& ray, TraceHit& hit, TraceScratch& scratch) const {
    EvalState st = make_state(impl_.get(), ray, eps_, scale_, scratch);
    TopContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.state = &st;
    ctx.accel = &impl_->top;
    ctx.tnear = ray.tnear;
    ctx.best = ray.tfar;
    ctx.best_unit = 0;
    ctx.found = false;
    const std::uint32_t always_offset = std::uint32_t(impl_->top.items.size());
    for (std::size_t i = 0; i < impl_->top.always.size(); ++i)
        try_unit_entry(ctx, always_offset + std::uint32_t(i), impl_->top.always[i], false);
    if (impl_->top.scene) {
        RTCRayHit rh = make_rayhit(st, ray.tnear, ctx.best);
        rtcIntersect1(impl_->top.scene, &ctx.rtc, &rh);
    }
    if (!ctx.found) return false;
    hit.t = ctx.best;
    hit.surface = ctx.best_end;
    return true;
}

bool CsgTracer::occluded(const TraceRay& ray, TraceScratch& scratch) const {
    EvalState st = make_state(impl_.get(), ray, eps_, scale_, scratch);
    TopContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.state = &st;
    ctx.accel = &impl_->top;
    ctx.tnear = ray.tnear;
    ctx.best = ray.tfar;
    ctx.best_unit = 0;
    ctx.found = false;
    for (std::uint32_t node : impl_->top.always)
        if (unit_blocks(ctx, node, false)) return true;
    if (!impl_->top.scene) return false;
    RTCRay r = make_rayhit(st, ray.tnear, ray.tfar).ray;
    rtcOccluded1(impl_->top.scene, &ctx.rtc, &r);
    return ctx.found;
}

glm::dvec3 CsgTracer::normal(const TraceHit& hit, const glm::dvec3& world_point) const {
    const csg::Leaf& leaf = impl_->scene.leaves[hit.surface.leaf];
    glm::dvec3 n_obj;
    if (leaf.kind == csg::PrimKind::Mesh) {  // the triangle's own normal (CCW seen from outside)
        const csg::Mesh& m = impl_->scene.meshes[leaf.mesh];
        const std::uint32_t* tri = &m.triangles[std::size_t(hit.surface.prim) * 3];
        n_obj = glm::cross(m.points[tri[1]] - m.points[tri[0]], m.points[tri[2]] - m.points[tri[0]]);
    } else {
        n_obj = csg::object_normal(leaf, leaf.object_from_world.point(world_point), hit.surface.part);
    }
    glm::dvec3 n = leaf.normal_to_world * n_obj;
    const double len = glm::length(n);
    n = len > 0 ? n / len : glm::dvec3(0, 0, 1);
    return hit.surface.flip ? -n : n;
}

}  // namespace kerf::render
