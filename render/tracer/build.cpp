// Builds a CsgTracer's Embree scenes once per scene (README.md, "Tracer
// design"): the tolerances from the scene's scale, the top BVH whose
// primitives are the root's units (closest-hit semantics, first_hit.cpp,
// shadow_rays.cpp) and an own BVH for every union or difference with more
// than kDirectChildren operands (node_spans.cpp). Boxes are rounded outwards
// and padded, so Embree's float traversal only ever culls.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "render/tracer/float_round.hpp"
#include "render/tracer/build.hpp"
#include "render/tracer/parallel_build.hpp"

namespace kerf::render {

namespace {

using csg::Node;
using csg::Op;

constexpr std::uint32_t kDirectChildren = 8;  // more children than this: own BVH
// From this many items on, a BVH is built for memory (docs/performance.md,
// "Memory"): Embree's compact layout and its low-quality (Morton) builder.
// Smaller ones, every reference model's among them, keep the high-quality
// build their trace times were measured with.
constexpr std::size_t kHugeAccel = std::size_t(1) << 16;

void embree_error(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "kerf: embree error %d: %s\n", int(code), message ? message : "");
}

// A bounded node's box relative to the frame, rounded outwards, plus slack
// for the float ray's own rounding (its origin lies within ~frame_radius,
// see make_state).
RTCBounds embree_box(const csg::Aabb& b, const glm::dvec3& frame, double frame_radius) {
    const glm::dvec3 lo = b.lo - frame, hi = b.hi - frame;
    const double pad = 1e-6 * frame_radius;
    RTCBounds r;
    r.lower_x = round_down(lo.x - pad - 1e-6 * std::abs(lo.x));
    r.lower_y = round_down(lo.y - pad - 1e-6 * std::abs(lo.y));
    r.lower_z = round_down(lo.z - pad - 1e-6 * std::abs(lo.z));
    r.upper_x = round_up(hi.x + pad + 1e-6 * std::abs(hi.x));
    r.upper_y = round_up(hi.y + pad + 1e-6 * std::abs(hi.y));
    r.upper_z = round_up(hi.z + pad + 1e-6 * std::abs(hi.z));
    r.align0 = r.align1 = 0;
    return r;
}

void bounds_callback(const RTCBoundsFunctionArguments* args) {
    const Accel* accel = static_cast<const Accel*>(args->geometryUserPtr);
    *args->bounds_o = embree_box(accel->nodes[accel->items[args->primID]].bounds, accel->frame, accel->frame_radius);
}

// Operands of the root's union chain, in order: the units. Only unions are
// stacked (with the next child to visit): a lattice's 10^5 leaves under one
// union go straight to the list.
std::vector<std::uint32_t> root_units(const csg::Scene& scene) {
    if (scene.nodes[scene.root].op != Op::Union) return {scene.root};
    std::vector<std::uint32_t> units;
    units.reserve(scene.nodes[scene.root].count);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> stack{{scene.root, 0}};
    while (!stack.empty()) {
        const Node& n = scene.nodes[stack.back().first];
        if (stack.back().second == n.count) {
            stack.pop_back();
            continue;
        }
        const std::uint32_t child = scene.children[n.first + stack.back().second++];
        if (scene.nodes[child].op == Op::Union)
            stack.push_back({child, 0});
        else
            units.push_back(child);
    }
    return units;
}

// A BVH's items: the bounded nodes, in order; the unbounded ones are
// tested always. An empty solid can never be hit.
void split_items(const csg::Scene& scene, const std::uint32_t* first, const std::uint32_t* last, Accel& accel) {
    accel.items.reserve(std::size_t(last - first));
    for (const std::uint32_t* it = first; it != last; ++it) {
        const csg::Aabb& b = scene.nodes[*it].bounds;
        if (b.empty()) continue;
        if (!finite_box(b))
            accel.always.push_back(*it);
        else
            accel.items.push_back(*it);
    }
}

}  // namespace

CsgTracer::Impl::~Impl() {
    if (top.bvh) rtcReleaseScene(top.bvh);
    if (ball_bvh) rtcReleaseScene(ball_bvh);
    for (auto& a : node_accels)
        if (a->bvh) rtcReleaseScene(a->bvh);
    for (RTCScene m : mesh_bvhs)
        if (m) rtcReleaseScene(m);
    if (device) rtcReleaseDevice(device);
}

void Accel::commit_now() const {
    const std::lock_guard lock(commit_lock);
    if (committed.load(std::memory_order_relaxed)) return;  // another thread built it meanwhile
    rtcCommitScene(bvh);
    check_embree(device, "the scene");
    committed.store(true, std::memory_order_release);
}

void CsgTracer::Impl::build_accel(Accel& accel, const std::vector<std::uint32_t>& nodes, bool top_level, bool lazy,
                                  const Accel* same) {
    if (same) {
        if (same != &accel) {  // &accel: its items were moved in by the caller
            accel.items = same->items;
            accel.always = same->always;
        }
    } else {
        split_items(scene, nodes.data(), nodes.data() + nodes.size(), accel);
    }
    // A few units are cheaper to box-test in a loop than through Embree, whose
    // per-query set-up costs about as much as tracing a background pixel.
    if (accel.items.size() <= kDirectChildren) return;
    accel.bvh = rtcNewScene(device);
    if (!accel.bvh) embree_failed(device, "the scene");
    const bool huge = accel.items.size() >= kHugeAccel;
    rtcSetSceneFlags(accel.bvh, huge ? RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT) : RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(accel.bvh, huge ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    if (!geom) embree_failed(device, "the scene");
    rtcSetGeometryUserPrimitiveCount(geom, unsigned(accel.items.size()));
    accel.nodes = scene.nodes.data();
    accel.frame = frame;
    accel.frame_radius = frame_radius;
    rtcSetGeometryUserData(geom, &accel);
    rtcSetGeometryBoundsFunction(geom, bounds_callback, nullptr);
    rtcSetGeometryIntersectFunction(geom, top_level ? top_intersect_callback : collect_callback);
    if (top_level) rtcSetGeometryOccludedFunction(geom, top_occluded_callback);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(accel.bvh, geom);
    rtcReleaseGeometry(geom);
    accel.device = device;
    accel.committed.store(false, std::memory_order_release);
    if (!lazy) accel.ready();  // now; else the first query's (Accel::ready)
}

// The units' balls as Embree's native spheres (render/README.md, "Ball
// BVH"): Embree tests them several to a BVH leaf with SIMD, so a ray that
// crosses a unit's box but misses its ball costs no callback. Built only
// when every bounded unit has a ball (otherwise the box BVH alone), on the
// double path (the float path's ball slack is far larger than this pad).
// Each sphere is the ball grown by kBallFloatPad of the scene's extent and
// of its centre's distance from the frame: beyond the float round-off of
// Embree's sphere test, of the rounded centre and of the per-ray slack the
// double tests add (which the query checks per ray, ball_path_fits).
void CsgTracer::Impl::build_ball_bvh() {
    if (use_float || !top.bvh || top.balls.size() != top.items.size() || !sphere_grid.empty()) return;
    for (const Ball& b : top.balls)
        if (b.r < 0) return;
    // Few boxes along a ray (cells_100: 2 on average) gain too little to pay
    // for the sphere tests (measured 1.1-1.2x slower there, 0.66-0.8x at
    // 20-60 crossings: docs/performance.md, "Ball BVH"). By Cauchy's formula
    // the mean number of boxes a random line through `reach` crosses is the
    // sum of their surface areas over reach's.
    const auto area = [](const csg::Aabb& b) {
        const glm::dvec3 e = b.hi - b.lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    };
    double crossings = 0;
    for (std::uint32_t unit : top.items) crossings += area(scene.nodes[unit].bounds);
    if (!(crossings >= kBallBvhCrossings * area(reach))) return;
    ball_r_min = std::numeric_limits<double>::infinity();
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    if (!geom) embree_failed(device, "the scene");
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                          4 * sizeof(float), top.items.size()));
    if (!v) {
        rtcReleaseGeometry(geom);
        embree_failed(device, "the scene");
    }
    for (std::size_t i = 0; i < top.items.size(); ++i) {
        const glm::dvec3 c = top.balls[i].c - frame;
        const double r = top.balls[i].r;
        ball_r_min = std::min(ball_r_min, r);
        v[4 * i + 0] = float(c.x);
        v[4 * i + 1] = float(c.y);
        v[4 * i + 2] = float(c.z);
        v[4 * i + 3] = round_up(r * (1 + kBallFloatPad) +
                                kBallFloatPad * (frame_radius + std::abs(c.x) + std::abs(c.y) + std::abs(c.z)));
    }
    rtcSetGeometryIntersectFilterFunction(geom, top_ball_filter);
    rtcSetGeometryOccludedFilterFunction(geom, top_ball_occluded_filter);
    rtcCommitGeometry(geom);
    ball_bvh = rtcNewScene(device);
    if (!ball_bvh) {
        rtcReleaseGeometry(geom);
        embree_failed(device, "the scene");
    }
    const bool huge = top.items.size() >= kHugeAccel;
    rtcSetSceneFlags(ball_bvh, huge ? RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT) : RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(ball_bvh, huge ? RTC_BUILD_QUALITY_LOW : RTC_BUILD_QUALITY_HIGH);
    rtcAttachGeometry(ball_bvh, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(ball_bvh);
    check_embree(device, "the scene");
}

void check_embree(RTCDevice device, const char* what) {
    if (const RTCError e = rtcGetDeviceError(device); e != RTC_ERROR_NONE) embree_failed(device, what, e);
}

void embree_failed(RTCDevice device, const char* what, RTCError e) {
    if (e == RTC_ERROR_NONE) e = rtcGetDeviceError(device);
    if (e == RTC_ERROR_OUT_OF_MEMORY) throw std::runtime_error(std::string("out of memory building ") + what);
    throw std::runtime_error(std::string("embree failed to build ") + what + " (error " + std::to_string(int(e)) + ")");
}

CsgTracer::CsgTracer(const csg::Scene& scene, bool use_float) : impl_(std::make_unique<Impl>(scene, use_float)) {
    impl_->device = rtcNewDevice(nullptr);
    if (!impl_->device) throw std::runtime_error("cannot create the Embree device");
    rtcSetDeviceErrorFunction(impl_->device, embree_error, nullptr);

    // A big root union's items (the lattices' 10^5 children, each a miss in
    // the node table) split out by one thread of the arena while the others
    // fill the tables below; the same list, taken by its BVH's build.
    const bool big_root = scene.root != csg::kNone && scene.nodes[scene.root].op == Op::Union &&
                          scene.nodes[scene.root].count >= kParallelBuild;
    Accel root_items;
    ConcurrentStep root_sort(big_root, [&] {
        if (!big_root) return;
        const std::uint32_t* kids = scene.children.data() + scene.nodes[scene.root].first;
        split_items(scene, kids, kids + scene.nodes[scene.root].count, root_items);
    });
    impl_->accel_of_node.assign(scene.nodes.size(), -1);
    // Every per-leaf and per-node table reserved at its size: grown by
    // doubling, each copy faulted in fresh pages (a third of the page
    // faults of building 10^5 spheres' tracer).
    reserve_populated(impl_->leaf_stretch, scene.leaves.size());
    impl_->leaf_stretch.resize(scene.leaves.size());
    impl_->leaf_shift_only.resize(scene.leaves.size());
    parallel_for_build(scene.leaves.size(), [&](std::size_t i) {
        const glm::dmat3& m = scene.leaves[i].object_from_world.linear;
        impl_->leaf_stretch[i] = std::sqrt(glm::dot(m[0], m[0]) + glm::dot(m[1], m[1]) + glm::dot(m[2], m[2]));
        impl_->leaf_shift_only[i] = m == glm::dmat3(1.0) ? 1 : 0;
    });
    const std::vector<std::uint32_t> units =
        scene.root == csg::kNone ? std::vector<std::uint32_t>{} : root_units(scene);
    impl_->local_tolerances(units);
    reserve_populated(impl_->padded, scene.nodes.size());
    impl_->padded.resize(scene.nodes.size());
    parallel_for_build(scene.nodes.size(), [&](std::size_t id) {
        const csg::Aabb& b = scene.nodes[id].bounds;
        const glm::dvec3 e(impl_->node_eps[id]);
        impl_->padded[id] = {b.lo - e, b.hi + e};
    });
    if (scene.root == csg::kNone) return;
    impl_->build_meshes();
    impl_->build_prism_grids();
    root_sort.join();
    for (std::uint32_t id = 0; id < scene.nodes.size(); ++id) {
        const Node& n = scene.nodes[id];
        const std::uint32_t skip = n.op == Op::Difference ? 1 : 0;
        if ((n.op == Op::Union || n.op == Op::Difference) && n.count - skip > kDirectChildren) {
            std::vector<std::uint32_t> kids(scene.children.begin() + n.first + skip,
                                            scene.children.begin() + n.first + n.count);
            impl_->node_accels.push_back(std::make_unique<Accel>());
            Accel& accel = *impl_->node_accels.back();
            // A difference's BVH waits for its first query (Accel::ready), but
            // not a huge one's (chosen when each item's box was stored until
            // the build; now the bounds callback makes them, so only the
            // build's timing would move, unmeasured). So does a big root union's, whose children are the units: the
            // top-level queries visit them, and nothing may ever ask the
            // root's own spans (the spheres_* lattices: 50 ms of build at 10⁵).
            const bool root_union = n.op == Op::Union && id == scene.root && kids.size() > Impl::kMaxTwoLevelUnits;
            const bool sorted = big_root && id == scene.root;
            if (sorted) {  // the step's lists, moved (10^6 items: 4 MB not copied into fresh pages)
                accel.items = std::move(root_items.items);
                accel.always = std::move(root_items.always);
            }
            impl_->build_accel(accel, kids, false, (n.op == Op::Difference && kids.size() < kHugeAccel) || root_union,
                               sorted ? &accel : nullptr);
            if (n.op == Op::Difference && accel.bvh) {
                std::vector<csg::Aabb> boxes;
                for (std::uint32_t item : accel.items) boxes.push_back(impl_->padded[item]);
                accel.grid.build(boxes);
                for (std::uint32_t& id : accel.grid.boxes) id = accel.items[id];  // the nodes themselves: one load less per candidate
            }
            impl_->accel_of_node[id] = std::int32_t(impl_->node_accels.size() - 1);
        }
    }
    impl_->leaf_pair.assign(scene.nodes.size(), 0);
    const auto analytic_leaf = [&](std::uint32_t node) {
        if (scene.nodes[node].op != Op::Leaf) return false;
        const csg::PrimKind k = scene.leaves[scene.nodes[node].first].kind;
        return k != csg::PrimKind::Mesh && k != csg::PrimKind::Prism && k != csg::PrimKind::Lathe;
    };
    impl_->leaf_minus.assign(scene.nodes.size(), 0);
    for (std::uint32_t id = 0; id < scene.nodes.size(); ++id) {
        const Node& n = scene.nodes[id];
        if (n.op == Op::Leaf || impl_->accel_of_node[id] >= 0 || n.count < 2) continue;
        bool leaves = true;
        for (std::uint32_t k = 0; k < n.count; ++k) leaves = leaves && analytic_leaf(scene.children[n.first + k]);
        impl_->leaf_pair[id] = leaves && n.count == 2;
        impl_->leaf_minus[id] = leaves && n.op == Op::Difference && n.count - 1 <= kDirectChildren;
    }
    impl_->grid_minus.assign(scene.nodes.size(), 0);
    for (std::uint32_t id = 0; id < scene.nodes.size(); ++id) {
        const std::int32_t ai = impl_->accel_of_node[id];
        const Node& n = scene.nodes[id];
        if (n.op != Op::Difference || ai < 0 || impl_->node_accels[std::size_t(ai)]->grid.empty()) continue;
        const Node& m = scene.nodes[scene.children[n.first]];
        impl_->grid_minus[id] = m.op == Op::Leaf && one_span_kind(scene.leaves[m.first].kind);
    }
    // Past the cones' units the top BVH waits (Accel::ready): a crowd of
    // bare spheres walks its grid instead (sphere_grid.hpp), and only rays
    // too far for the grid's margin would ask it.
    // A root union of no unions (the lattices): its units are its children,
    // whose BVH items were just split out (each a miss in the node table at
    // 10^5).
    const std::int32_t root_accel = impl_->accel_of_node[scene.root];
    const Node& root = scene.nodes[scene.root];
    const bool same = root_accel >= 0 && root.op == Op::Union && root.count == units.size() &&
                      std::equal(units.begin(), units.end(), scene.children.begin() + root.first);
    impl_->build_accel(impl_->top, units, true, units.size() > Impl::kMaxTwoLevelUnits,
                       same ? impl_->node_accels[std::size_t(root_accel)].get() : nullptr);
    if (impl_->top.items.size() == 1 && impl_->top.always.empty()) impl_->lone_unit = impl_->top.items[0];
    if (impl_->lone_unit != csg::kNone && impl_->grid_minus[impl_->lone_unit]) impl_->plate_unit = impl_->lone_unit;
    // The shadow rays' per-leaf tables (find_convex_units) are read by
    // nothing else here: a big scene's are filled by one thread while the
    // others build the balls, the grid and the rest (they write disjoint
    // members; the same bits). Joined before the constructor returns or
    // throws (`convex` waits in its destructor).
    ConcurrentStep convex(scene.nodes.size() >= kParallelBuild, [this] { impl_->find_convex_units(); });
    impl_->ball_slack = use_float ? 1e-5 : 1e-12;  // float sphere tests round at ~1e-7 of |c - o|
    // A crowd of bare spheres (every unit a sphere leaf: the spheres_*
    // lattices) up to kMaxTwoLevelUnits keeps their balls, though each
    // repeats its leaf's own test: they bring tile culling by ball and ray
    // cones (bare_spheres.hpp). Beyond, a grid of their balls that rays
    // walk (sphere_grid.hpp; without it the ball BVH alone is slower on
    // bare spheres than the box BVH: spheres_10000 at 1024², 2,518 M
    // instructions against 2,138 M).
    const std::vector<std::uint32_t>& top_items = impl_->top.items;
    impl_->bare_spheres = !use_float && impl_->top.always.empty() && top_items.size() > 1 &&
                          std::all_of(top_items.begin(), top_items.end(), [&](std::uint32_t u) {
                              return scene.nodes[u].op == Op::Leaf && scene.leaves[scene.nodes[u].first].kind == csg::PrimKind::Sphere;
                          });
    impl_->top.balls = unit_balls(scene, top_items, impl_->node_eps, impl_->bare_spheres);
    if (!impl_->top.balls.empty())
        impl_->top.sphere_minus = sphere_minus_units(scene, impl_->top.items, impl_->node_eps, impl_->top.subs);
    // solve_ahead's leaf: the sphere minuend of a one-unit scene's leaf
    // minus leaves (a grooved sphere), whose every camera query that passes
    // the unit's ball starts by solving it (leaf_minus_spans). Not where the
    // ball chords decide most rays first (a sphere minus a few balls), nor
    // for other kinds (a box minuend: the checkered cube's camera rays
    // would solve it ahead for 8 % more instructions, 512²).
    if (!use_float && impl_->lone_unit != csg::kNone && impl_->leaf_minus[impl_->lone_unit]) {
        const bool chords = !impl_->top.sphere_minus.empty() && impl_->top.sphere_minus[0].r_in >= 0;
        const std::uint32_t leaf = scene.nodes[scene.children[scene.nodes[impl_->lone_unit].first]].first;
        if (!chords && scene.leaves[leaf].kind == csg::PrimKind::Sphere) impl_->ahead_leaf = leaf;
    }
    if (impl_->top.always.empty()) {
        // Padded beyond every Embree box and the node box tests' slack, so
        // the early out never culls what they would keep, and a float ray
        // started at its entry (make_state) has every box ahead of it.
        csg::Aabb reach;
        double eps = 0;
        for (std::uint32_t unit : impl_->top.items) {
            reach.extend(scene.nodes[unit].bounds);
            eps = std::max(eps, impl_->node_eps[unit]);
        }
        const double pad = 4e-6 * impl_->frame_radius + 4 * eps;
        if (!reach.empty()) reach = {reach.lo - glm::dvec3(pad), reach.hi + glm::dvec3(pad)};
        impl_->reach = reach;
        // (Past TowardLight::kMaxUnits, not even its per-unit input: 8 MB of
        // peak at 10⁶ units.) Its lights and radii need no grid: a big
        // crowd's are found by one thread of the arena while the others
        // build the grid (the balls, read by both, are cleared only after).
        const bool lit_crowd = impl_->bare_spheres && impl_->top.items.size() <= TowardLight::kMaxUnits;
        ConcurrentStep toward_radii(lit_crowd && impl_->top.items.size() >= kParallelBuild, [&] {
            if (!lit_crowd) return;
            std::vector<double> leaf_eps;
            leaf_eps.reserve(impl_->top.items.size());
            for (std::uint32_t unit : impl_->top.items) leaf_eps.push_back(impl_->leaf_eps[scene.nodes[unit].first]);
            std::vector<glm::dvec3> lights;
            for (const csg::Light& light : scene.lights)
                if (!light.directional && light.shadows && !(light.radius > 0)) lights.push_back(light.position);
            impl_->toward_light.build_radii(impl_->top.balls, leaf_eps, impl_->eps_per_distance, impl_->frame_radius,
                                            reach, lights);
        });
        if (impl_->bare_spheres && impl_->top.items.size() > Impl::kMaxTwoLevelUnits)
            impl_->sphere_grid.build(reach, impl_->top.balls);
        toward_radii.join();
        if (impl_->bare_spheres && impl_->top.items.size() > Impl::kMaxTwoLevelUnits && impl_->sphere_grid.empty()) {
            // (not expected of bare spheres) as before: the box BVH, no balls, no TowardLight
            impl_->bare_spheres = false;
            impl_->top.balls.clear();
            impl_->top.sphere_minus.clear();
            impl_->toward_light = TowardLight{};
        }
        if (lit_crowd && impl_->bare_spheres) impl_->toward_light.attach(impl_->top.balls, reach, impl_->sphere_grid);
        const std::vector<std::uint32_t>& items = impl_->top.items;
        const csg::Camera& cam = scene.camera;
        const bool pinhole = cam.projection == csg::Projection::Planar && !cam.orthographic && !(cam.aperture > 0);
        const bool all_balls = impl_->top.balls.size() == items.size() &&
                               std::all_of(impl_->top.balls.begin(), impl_->top.balls.end(),
                                           [](const Ball& b) { return b.r >= 0; });
        std::vector<csg::Aabb> boxes;
        if (pinhole && all_balls && items.size() > Impl::kCullUnits && items.size() <= Impl::kMaxSpreadUnits) {
            for (std::uint32_t unit : items)  // (the padding below: unused with a ball)
                boxes.push_back({scene.nodes[unit].bounds.lo - glm::dvec3(pad), scene.nodes[unit].bounds.hi + glm::dvec3(pad)});
            impl_->cull_units = spread_cull_bounds(impl_->top.balls, boxes, Impl::kCullUnits);
        }
        if (impl_->cull_units.empty() && (items.size() > 1 || (items.size() == 1 && !impl_->top.balls.empty())))
            if (items.size() <= Impl::kCullUnits || (pinhole && all_balls && items.size() <= Impl::kMaxTwoLevelUnits))
                for (std::size_t i = 0; i < items.size(); ++i) {
                    const csg::Aabb& b = scene.nodes[items[i]].bounds;
                    impl_->cull_units.push_back({i < impl_->top.balls.size() ? impl_->top.balls[i] : Ball{},
                                                 b.empty() ? b : csg::Aabb{b.lo - glm::dvec3(pad), b.hi + glm::dvec3(pad)}});
                }
        if (pinhole && !impl_->cull_units.empty()) {
            // tile_cull.cpp's ball_outside with every corner ray at o.
            const glm::dvec3 o = cam.position;
            impl_->cull_origin = o;
            const double o_len = glm::length(o);
            for (const Impl::CullBound& u : impl_->cull_units) {
                const glm::dvec3 w = u.ball.c - o;
                const double w1 = std::abs(w.x) + std::abs(w.y) + std::abs(w.z);
                const double r = grown_radius(u.ball.r, 4 * impl_->eps_per_distance * o_len, impl_->ball_slack, w1);
                impl_->cull_from.push_back({w, r + 1e-9 * (w1 + r + o_len + 1e-300)});
            }
        }
        impl_->build_ball_bvh();
        impl_->build_apexes();
    }
    convex.join();
    if (impl_->sphere_grid.empty()) impl_->top.ready();
    impl_->float_rays = impl_->top.bvh != nullptr || impl_->ball_bvh != nullptr;
}

CsgTracer::~CsgTracer() = default;

}  // namespace kerf::render
