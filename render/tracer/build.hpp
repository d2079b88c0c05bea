// What a CsgTracer builds once and every query then only reads: the Embree
// device, the top BVH over the root's units, the own BVHs of large union and
// difference nodes (a difference's committed on first use: Accel::ready),
// and one triangle scene per mesh. Its own header because
// the build (build.cpp, mesh_spans.cpp) and the per-ray files all
// need the layout.
#pragma once
#include <cmath>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/primitives/prism_grid.hpp"
#include "render/tracer/box_grid.hpp"
#include "render/tracer/sphere_grid.hpp"
#include "render/tracer/toward_light.hpp"
#include "render/tracer/tracer.hpp"
#include "render/tracer/unit_balls.hpp"

namespace kerf::render {

// A BVH over some nodes (the root's units, or a large node's children).
struct Accel {
    RTCScene bvh = nullptr;            // null: few items, tested one by one
    std::vector<std::uint32_t> items;  // node per Embree primID
    // For Embree's bounds callback, which boxes each item from its node
    // when the BVH is built (embree_box in build.cpp): a stored box per
    // item was 32 bytes a unit, kept until a lazy build that the bare-sphere
    // crowds never ask for (docs/performance.md, "The front end, again").
    const csg::Node* nodes = nullptr;
    glm::dvec3 frame{0.0};
    double frame_radius = 1;
    std::vector<std::uint32_t> always;  // unbounded nodes (half-spaces): tested for every ray
    std::vector<Ball> balls;            // top only: per item, or empty (unit_balls.hpp)
    std::vector<SphereMinus> sphere_minus;  // top only: per item, or empty (ball_chords.hpp)
    std::vector<SubBound> subs;             // their subtrahends
    BoxGrid grid;  // a big difference's subtrahends, listing node ids (box_grid.hpp); else empty

    // A big difference's BVH is committed (built) by the first query that
    // needs it, not with the tracer: its grid answers nearly every query
    // (holes_40 makes none of Embree), and the build was ~1 ms of serial
    // start-up (docs/performance.md, "Holes, the process around the
    // render").
    // Thread-safe: the first caller builds under the lock, the others wait.
    void ready() const {
        if (committed.load(std::memory_order_acquire)) return;
        commit_now();
    }
    mutable std::atomic<bool> committed{true};  // false: `bvh` holds its geometry, not yet built
    RTCDevice device = nullptr;                 // for the error check after a late commit

private:
    void commit_now() const;  // build.cpp
    mutable std::mutex commit_lock;
};

// Embree reports failures (out of memory above all) as null handles and
// buffers and through the device error: these turn them into exceptions
// (render() fails, the command exits 3 with the message). embree_failed
// reads the device error when `e` is none.
void check_embree(RTCDevice device, const char* what);  // after commits
[[noreturn]] void embree_failed(RTCDevice device, const char* what, RTCError e = RTC_ERROR_NONE);

struct CsgTracer::Impl {
    const csg::Scene& scene;
    bool use_float;
    RTCDevice device = nullptr;
    Accel top;
    // The padded box around every bounded unit; everything() when a unit is
    // unbounded. A ray whose line misses it hits nothing (first_hit.cpp).
    csg::Aabb reach = csg::Aabb::everything();
    // Scenes of at most kCullUnits units, all bounded: each unit's ball
    // (unit_balls.hpp) or else its box padded as `reach` is, for culling
    // image blocks unit by unit (tile_cull.cpp). Empty otherwise.
    struct CullBound {
        Ball ball;      // r < 0: none, use `box`
        csg::Aabb box;
    };
    // (A block's test costs ~4 planes per unit: with 100 units it still
    // pays, 8-9 % of a 512² render's instructions on shell_100.)
    static constexpr std::size_t kCullUnits = 128;
    std::vector<CullBound> cull_units;
    // Crowds up to kMaxTwoLevelUnits units, all with balls, seen by a
    // pinhole camera are culled unit by unit too: per unit, what the ball
    // test over a quad finds when its corner rays all start at the camera's
    // position (cull_origin) is found once, w = c - o and the ball's radius
    // grown by every slack (tile_cull.cpp, ball_outside), so a unit costs a
    // tile four dot products at most, and a block only its tile's units.
    // (Also for the scenes of few units.) Empty otherwise.
    struct CullFrom {
        glm::dvec3 w;
        double r;
    };
    glm::dvec3 cull_origin{0.0};
    std::vector<CullFrom> cull_from;
    std::vector<csg::Aabb> padded;            // per node: bounds grown by node_eps (box tests)
    // Local tolerances (docs/accuracy.md "Far from the origin"): the
    // degenerate rule's world length per node, from the sizes and positions
    // of the leaves of the unit it belongs to, never from the whole scene,
    // so a far-away part does not coarsen the rest. leaf_eps: the same per
    // leaf (shading's surface offset).
    std::vector<double> node_eps, leaf_eps;
    double eps_per_distance = 0;              // added per unit of the ray origin's |o|
    double ball_slack = 1e-12;                // unit balls: relative round-off of the leaf tests
    // Embree's float BVHs hold boxes relative to `frame` (the middle of the
    // bounded units) and rays start at o - frame: a scene far from the
    // origin keeps float precision. frame_radius: the largest |corner -
    // frame| of a bounded unit (float slack of boxes and t windows).
    glm::dvec3 frame{0.0};
    // The top units' balls as Embree's native spheres, for rays whose window
    // starts outside `reach` (first_hit.cpp; render/README.md, "Ball BVH");
    // null unless every bounded unit has a ball. ball_r_min: the smallest.
    RTCScene ball_bvh = nullptr;
    double ball_r_min = 0;
    static constexpr double kBallFloatPad = 4e-6;
    static constexpr double kBallBvhCrossings = 8;  // built from this many boxes per line on
    double frame_radius = 1;
    std::vector<std::int32_t> accel_of_node;  // -1: children evaluated directly
    std::vector<std::unique_ptr<Accel>> node_accels;
    std::vector<double> leaf_stretch;         // per leaf: Frobenius norm of object_from_world.linear
    std::vector<std::uint8_t> leaf_shift_only;  // per leaf: 1 if object_from_world.linear is the identity
    // A world point or direction in leaf `id`'s object space. A leaf only
    // moved (most are: translate, or none) skips the matrix: 1·x + 0·y +
    // 0·z is x, so the numbers are the same. One place for every path
    // whose numbers must agree bit for bit (a leaf's spans and
    // solve_ahead's, which the query takes for its own; the clearance
    // tests; the normals).
    glm::dvec3 leaf_point(std::uint32_t id, const glm::dvec3& x) const {
        const csg::Affine& m = scene.leaves[id].object_from_world;
        return leaf_shift_only[id] ? x + m.offset : m.point(x);
    }
    glm::dvec3 leaf_vector(std::uint32_t id, const glm::dvec3& v) const {
        return leaf_shift_only[id] ? v : scene.leaves[id].object_from_world.vector(v);
    }
    // Per node: 1 for a union, intersection or difference of exactly two
    // analytic leaves (no mesh, prism or lathe), evaluated in one step
    // (node_spans.cpp, leaf_pair_spans).
    std::vector<std::uint8_t> leaf_pair;
    // Per node: 1 for a difference of an analytic leaf minus at most
    // kDirectChildren analytic leaves, asked for its first entry or any span
    // in one step (leaf_minus.cpp).
    std::vector<std::uint8_t> leaf_minus;
    // The leaf CsgTracer::solve_ahead solves (build.cpp says which); kNone: none.
    std::uint32_t ahead_leaf = csg::kNone;
    // Per node: 1 for a difference with a subtrahend grid (box_grid.hpp)
    // whose minuend is a one-span leaf (sphere, box, cylinder): a unit's
    // first entry is then found in locals (difference_first_entry.cpp,
    // grid_first_entry), without the span stack.
    std::vector<std::uint8_t> grid_minus;
    // The root's one unit (node) when there are no others, bounded or not
    // (a grooved sphere, a lens, a holed plate alone), else kNone; with a
    // single item the top has no BVH. plate_unit: the same when it is a
    // grid_minus difference (first_hit.cpp asks it directly).
    std::uint32_t lone_unit = csg::kNone;
    std::uint32_t plate_unit = csg::kNone;
    // Per leaf: the unit (top item index; unbounded units after the items)
    // that lies wholly inside it when the leaf is convex, else kNone: a
    // shadow ray leaving its surface outwards skips that unit (Departure).
    std::vector<std::uint32_t> convex_unit;
    // Per leaf: when it is a convex subtrahend (sphere, box, cylinder) of a
    // difference that holds a unit, that unit's root node and the leaf's
    // node (Departure::hollow, into), else kNone.
    std::vector<std::uint32_t> hollow_unit, hollow_node;
    // Per leaf with a hollow_unit: 1 when the leaf reaches out of that
    // unit's padded box (a drilled hole through a plate), so a ray may leave
    // the box while still inside the leaf (shadow_rays.cpp, stays_inside).
    std::vector<std::uint8_t> hollow_exits;
    // Whether queries go through an Embree BVH of units (the top one, the
    // balls'): then every ray needs its float copy at once (make_state);
    // else a query through a node's own BVH makes it when it needs it
    // (float_ray_now): a holed plate's grid answers nearly all of them.
    bool float_rays = true;
    std::vector<RTCScene> mesh_bvhs;        // per csg::Mesh used by a leaf (object space)
    std::vector<csg::Aabb> mesh_boxes;        // object-space bounds of each mesh
    std::vector<csg::PrismGrid> prism_grids;  // per Scene::polygons entry used by a prism (prism_spans.cpp)
    // The camera's and the point lights' positions (ray_cones.hpp), when
    // every unit has a ball and they are few; else empty.
    std::vector<Apex> apexes;
    // Every unit a sphere leaf with a ball, on the double path: a cone's
    // units are visited in locals (bare_spheres.hpp).
    bool bare_spheres = false;
    // Such a crowd of more than kMaxTwoLevelUnits units: its cells, which
    // its rays walk instead of cones (sphere_grid.hpp).
    SphereGrid sphere_grid;
    // Such a crowd's units that may block a shadow ray from one of them to
    // a point light (toward_light.hpp).
    TowardLight toward_light;
    // One level of cones up to kMaxConeUnits units, two up to
    // kMaxTwoLevelUnits (ray_cones.hpp); beyond, the ball BVH alone (the
    // apexes' per-unit arrays grow with the units, and no scene was measured).
    // Crowds of spread sizes: two levels up to kMaxSpreadUnits (spiral_10000),
    // a wide cone listing at most kSpreadWideUnits, a narrow one
    // kSpreadNarrowUnits (ray_cones.cpp, build_apexes).
    static constexpr std::size_t kMaxConeUnits = 256, kMaxTwoLevelUnits = 4096;
    static constexpr std::size_t kMaxSpreadUnits = 1 << 16, kSpreadWideUnits = 1024, kSpreadNarrowUnits = 64;
    // Unique per tracer in the process: a thread's cones name their owner
    // by it, not by address (a tracer built where a freed one stood must
    // not take that one's cones, whose unit indices are another scene's).
    const std::uint64_t id = next_id();

    Impl(const csg::Scene& s, bool f) : scene(s), use_float(f) {}
    static std::uint64_t next_id() {
        static std::atomic<std::uint64_t> counter{0};
        return ++counter;
    }
    ~Impl();
    // `lazy`: leave the commit to the first query (Accel::ready).
    // `same`: an accel already built of the same nodes in the same order,
    // whose items and unbounded nodes are copied rather than split again
    // (`accel` itself: they were moved in already).
    void build_accel(Accel& accel, const std::vector<std::uint32_t>& nodes, bool top_level, bool lazy = false,
                     const Accel* same = nullptr);
    void local_tolerances(const std::vector<std::uint32_t>& units);  // build.cpp
    void build_meshes();  // mesh_spans.cpp
    void build_prism_grids();  // prism_spans.cpp
    void find_convex_units();  // shadow_rays.cpp
    void build_ball_bvh();     // build.cpp, after the balls and `reach`
    void build_apexes();       // ray_cones.cpp, after the balls and `reach`
};

// A crowd's largest `keep` units' balls and one ball around the rest, when
// the rest crowd one spot; else empty (spread_cull.cpp).
std::vector<CsgTracer::Impl::CullBound> spread_cull_bounds(const std::vector<Ball>& balls,
                                                           const std::vector<csg::Aabb>& boxes, std::size_t keep);

// Embree callbacks the build installs, each defined beside the query it serves.
void top_intersect_callback(const RTCIntersectFunctionNArguments* args);  // first_hit.cpp
void top_occluded_callback(const RTCOccludedFunctionNArguments* args);    // shadow_rays.cpp
void collect_callback(const RTCIntersectFunctionNArguments* args);        // node_spans.cpp
void top_ball_filter(const RTCFilterFunctionNArguments* args);            // first_hit.cpp
void top_ball_occluded_filter(const RTCFilterFunctionNArguments* args);   // shadow_rays.cpp

// Leaves with one span per line whatever the window (sphere, box,
// cylinder): a subtrahend a ray leaves only once, whose span found on one
// window is what any overlapping window gives.
inline bool one_span_kind(csg::PrimKind kind) {
    return kind == csg::PrimKind::Sphere || kind == csg::PrimKind::Box || kind == csg::PrimKind::Cylinder;
}

// Whether a box is bounded (half-spaces and what contains them are not):
// solids lie within csg::kRenderableRange, so anything beyond is infinite.
inline bool finite_box(const csg::Aabb& b) {
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(b.lo[i]) < csg::kRenderableRange && std::abs(b.hi[i]) < csg::kRenderableRange)) return false;
    return true;
}

// Outward (CCW seen from outside) normal of a mesh triangle, not normalised.
// Crossing orientation (mesh_spans.cpp) and hit normals (surface_normal.cpp)
// must use the same one.
inline glm::dvec3 triangle_normal(const csg::Mesh& m, std::uint32_t prim) {
    const std::uint32_t* tri = &m.triangles[std::size_t(prim) * 3];
    return glm::cross(m.points[tri[1]] - m.points[tri[0]], m.points[tri[2]] - m.points[tri[0]]);
}

}  // namespace kerf::render
