// The Embree floor and the CSG tax (docs/performance.md, "Embree floor and
// the CSG tax"): a kerf scene is evaluated and lowered by kerf's own
// pipeline, then its leaves are traced as ONE union with a plain Embree
// nearest-hit query, no CSG: the same primary rays (pixel centres, 1 spp)
// and one shadow ray per hit and shadowed light facing the surface, as
// kerf's Whitted shader sends them. Spheres that are spheres in the world
// (uniform scale) are Embree's native sphere points, meshes its native
// triangles, every other analytic leaf a user geometry whose callback runs
// kerf's own primitive test (render/primitives, double). kerf's render()
// runs in the same process on the same csg::Scene, alternating with the
// floor, and the CSG tax is the ratio of their rays per second per core.
//   bench_floor SCENE.sdl [size=1024] [threads=1] [runs=5]
// Prints one line per run and a `summary:` line (bench/floor.py reads it).
#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/camera.hpp"
#include "render/lights.hpp"
#include "render/primitives/primitives.hpp"
#include "render/render.hpp"
#include "render/tracer/tracer.hpp"  // tile_misses_box: the floor culls tiles as kerf does

using namespace kerf;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Counts {
    std::uint64_t primary = 0, shadow = 0;
    std::uint64_t rays() const { return primary + shadow; }
};

// The leaves as Embree geometry: which leaf each primitive of each kind is.
struct Floor {
    const csg::Scene* scene = nullptr;
    RTCDevice device = nullptr;
    RTCScene bvh = nullptr;
    unsigned sphere_geom = RTC_INVALID_GEOMETRY_ID, user_geom = RTC_INVALID_GEOMETRY_ID;
    std::vector<std::uint32_t> sphere_leaf, user_leaf;
    std::vector<unsigned> mesh_geom_leaf;  // geometry id -> leaf, for triangle geometries
    std::size_t triangles = 0, skipped = 0;
    double offset = 1e-6;  // shadow rays start this far off the surface (world units)
    csg::Aabb reach;       // the box of every leaf traced

    ~Floor() {
        if (bvh) rtcReleaseScene(bvh);
        if (device) rtcReleaseDevice(device);
    }
};

// A sphere leaf whose world shape is a sphere: its linear map is a
// rotation (or mirror) times one scale.
bool round_in_world(const csg::Leaf& leaf, double& scale) {
    const glm::dmat3& m = leaf.world_from_object.linear;
    const double s2 = glm::dot(m[0], m[0]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(glm::dot(m[i], m[j]) - (i == j ? s2 : 0.0)) > 1e-12 * s2) return false;
    scale = std::sqrt(s2);
    return true;
}

void user_bounds(const RTCBoundsFunctionArguments* a) {
    const Floor& f = *static_cast<const Floor*>(a->geometryUserPtr);
    const csg::Aabb& b = f.scene->leaves[f.user_leaf[a->primID]].bounds;
    // Rounded outwards to float.
    a->bounds_o->lower_x = std::nextafter(float(b.lo.x), -INFINITY);
    a->bounds_o->lower_y = std::nextafter(float(b.lo.y), -INFINITY);
    a->bounds_o->lower_z = std::nextafter(float(b.lo.z), -INFINITY);
    a->bounds_o->upper_x = std::nextafter(float(b.hi.x), INFINITY);
    a->bounds_o->upper_y = std::nextafter(float(b.hi.y), INFINITY);
    a->bounds_o->upper_z = std::nextafter(float(b.hi.z), INFINITY);
}

// The leaf's spans along the (float) Embree ray, in kerf's double test.
int leaf_spans(const Floor& f, unsigned prim, const RTCRay& r, csg::Span<double> (&sp)[csg::kMaxSpans]) {
    const csg::Leaf& leaf = f.scene->leaves[f.user_leaf[prim]];
    const glm::dvec3 o = leaf.object_from_world.point({r.org_x, r.org_y, r.org_z});
    const glm::dvec3 d = leaf.object_from_world.vector({r.dir_x, r.dir_y, r.dir_z});
    return csg::intersect_leaf<double>(leaf, o, d, sp, r.tnear, r.tfar);
}

void user_intersect(const RTCIntersectFunctionNArguments* a) {
    if (!a->valid[0]) return;
    const Floor& f = *static_cast<const Floor*>(a->geometryUserPtr);
    RTCRayHit& rh = *reinterpret_cast<RTCRayHit*>(a->rayhit);
    csg::Span<double> sp[csg::kMaxSpans];
    const int n = leaf_spans(f, a->primID, rh.ray, sp);
    for (int i = 0; i < n; ++i) {
        // The first surface crossing on the window: an entry, or the exit
        // of a span the ray starts in.
        const bool entry = sp[i].t0 > rh.ray.tnear;
        const double t = entry ? sp[i].t0 : sp[i].t1;
        if (!(t > rh.ray.tnear && t < rh.ray.tfar)) continue;
        rh.ray.tfar = float(t);
        rh.hit.geomID = a->geomID;
        rh.hit.primID = a->primID;
        rh.hit.u = float(entry ? sp[i].part0 : sp[i].part1);  // the surface part, for the normal
        rh.hit.v = entry ? 0.f : 1.f;
        return;
    }
}

void user_occluded(const RTCOccludedFunctionNArguments* a) {
    if (!a->valid[0]) return;
    const Floor& f = *static_cast<const Floor*>(a->geometryUserPtr);
    RTCRay& r = *reinterpret_cast<RTCRay*>(a->ray);
    csg::Span<double> sp[csg::kMaxSpans];
    const int n = leaf_spans(f, a->primID, r, sp);
    for (int i = 0; i < n; ++i)
        if (std::min<double>(sp[i].t1, r.tfar) > std::max<double>(sp[i].t0, r.tnear)) {
            r.tfar = -INFINITY;
            return;
        }
}

void build(Floor& f, const csg::Scene& s, bool native) {
    f.scene = &s;
    f.device = rtcNewDevice(nullptr);
    if (!f.device) throw std::runtime_error("cannot create the Embree device");
    f.bvh = rtcNewScene(f.device);
    std::vector<float> balls;  // x, y, z, r
    csg::Aabb all;
    for (std::uint32_t i = 0; i < s.leaves.size(); ++i) {
        const csg::Leaf& leaf = s.leaves[i];
        double scale = 1;
        if (leaf.kind == csg::PrimKind::Plane || leaf.kind == csg::PrimKind::Prism || leaf.kind == csg::PrimKind::Lathe) {
            ++f.skipped;  // unbounded, or a primitive with its own entry point: not in the floor
            continue;
        }
        all.extend(leaf.bounds);
        if (leaf.kind == csg::PrimKind::Mesh) {
            const csg::Mesh& m = s.meshes[leaf.mesh];
            RTCGeometry g = rtcNewGeometry(f.device, RTC_GEOMETRY_TYPE_TRIANGLE);
            auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                  3 * sizeof(float), m.points.size()));
            for (std::size_t k = 0; k < m.points.size(); ++k) {
                const glm::dvec3 p = leaf.world_from_object.point(m.points[k]);
                v[3 * k] = float(p.x), v[3 * k + 1] = float(p.y), v[3 * k + 2] = float(p.z);
            }
            auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                     3 * sizeof(unsigned), m.triangles.size() / 3));
            std::copy(m.triangles.begin(), m.triangles.end(), t);
            f.triangles += m.triangles.size() / 3;
            rtcCommitGeometry(g);
            const unsigned id = rtcAttachGeometry(f.bvh, g);
            rtcReleaseGeometry(g);
            if (f.mesh_geom_leaf.size() <= id) f.mesh_geom_leaf.resize(id + 1, csg::kNone);
            f.mesh_geom_leaf[id] = i;
        } else if (native && leaf.kind == csg::PrimKind::Sphere && round_in_world(leaf, scale)) {
            const glm::dvec3 c = leaf.world_from_object.offset;
            balls.insert(balls.end(), {float(c.x), float(c.y), float(c.z), float(leaf.p[0] * scale)});
            f.sphere_leaf.push_back(i);
        } else {
            f.user_leaf.push_back(i);
        }
    }
    if (!balls.empty()) {
        RTCGeometry g = rtcNewGeometry(f.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                              4 * sizeof(float), balls.size() / 4));
        std::copy(balls.begin(), balls.end(), v);
        rtcCommitGeometry(g);
        f.sphere_geom = rtcAttachGeometry(f.bvh, g);
        rtcReleaseGeometry(g);
    }
    if (!f.user_leaf.empty()) {
        RTCGeometry g = rtcNewGeometry(f.device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, unsigned(f.user_leaf.size()));
        rtcSetGeometryUserData(g, &f);
        rtcSetGeometryBoundsFunction(g, user_bounds, &f);
        rtcSetGeometryIntersectFunction(g, user_intersect);
        rtcSetGeometryOccludedFunction(g, user_occluded);
        rtcCommitGeometry(g);
        f.user_geom = rtcAttachGeometry(f.bvh, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(f.bvh);
    if (rtcGetDeviceError(f.device) != RTC_ERROR_NONE) throw std::runtime_error("embree failed to build the floor");
    if (!all.empty()) f.offset = 1e-6 * glm::length(all.hi - all.lo);
    f.reach = all;
}

// World unit normal at the hit, facing the ray.
glm::dvec3 hit_normal(const Floor& f, const RTCRayHit& rh, const glm::dvec3& p, const glm::dvec3& d) {
    glm::dvec3 n;
    if (rh.hit.geomID == f.user_geom) {
        const csg::Leaf& leaf = f.scene->leaves[f.user_leaf[rh.hit.primID]];
        n = leaf.normal_to_world(csg::object_normal(leaf, leaf.object_from_world.point(p), std::uint8_t(rh.hit.u)));
    } else {
        n = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};  // spheres and triangles: Embree's geometric normal
    }
    const double len = glm::length(n);
    n = len > 0 ? n / len : glm::dvec3(0, 0, 1);
    return glm::dot(n, d) > 0 ? -n : n;
}

RTCRay float_ray(const glm::dvec3& o, const glm::dvec3& d, double tfar) {
    RTCRay r{};
    r.org_x = float(o.x), r.org_y = float(o.y), r.org_z = float(o.z);
    r.dir_x = float(d.x), r.dir_y = float(d.y), r.dir_z = float(d.z);
    r.tnear = 0;
    r.tfar = tfar == kInf ? INFINITY : float(tfar);
    r.mask = ~0u;
    r.flags = 0;
    return r;
}

// One pixel: its centre ray, and at a hit a shadow ray per shadowed light
// that faces the surface (kerf's point-light rule; a spherical light gets
// one ray to its centre here).
void trace_pixel(const Floor& f, const render::CameraModel& cam, const std::vector<csg::Light>& lights, int x, int y,
                 RTCIntersectContext& ctx, Counts& c) {
    ++c.primary;
    glm::dvec3 o, d;
    if (!cam.ray(x + 0.5, y + 0.5, o, d)) return;
    RTCRayHit rh{};
    rh.ray = float_ray(o, d, kInf);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(f.bvh, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return;
    const glm::dvec3 p = o + double(rh.ray.tfar) * d;
    const glm::dvec3 n = hit_normal(f, rh, p, d);
    const glm::dvec3 start = p + f.offset * n;
    for (const csg::Light& light : lights) {
        render::LightView view;
        if (!light.shadows || !render::view_light(light, start, view) || glm::dot(n, view.l) <= 0) continue;
        ++c.shadow;
        RTCRay sr = float_ray(start, view.l, view.dist);
        rtcOccluded1(f.bvh, &ctx, &sr);
    }
}

// The whole image in 32×32 tiles over `threads` TBB workers, as kerf's
// tiles.hpp, and culled as kerf culls them: a tile whose corner rays miss the
// box of all leaves is not traced, its pixels still count as primary rays
// (kerf counts its culled pixels too).
Counts trace_image(const Floor& f, const csg::Scene& s, int size, tbb::task_arena& arena) {
    const render::CameraModel cam(s.camera, size, size);
    std::vector<csg::Light> lights = s.lights;
    for (csg::Light& l : lights) l.direction = glm::normalize(l.direction);
    constexpr int kTile = 32;
    const int tiles_x = (size + kTile - 1) / kTile, tiles = tiles_x * tiles_x;
    std::atomic<std::uint64_t> primary{0}, shadow{0};
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& r) {
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            Counts c;
            for (int tile = r.begin(); tile != r.end(); ++tile) {
                const int x0 = (tile % tiles_x) * kTile, y0 = (tile / tiles_x) * kTile;
                const int x1 = std::min(x0 + kTile, size), y1 = std::min(y0 + kTile, size);
                if (cam.corners_bound_tiles()) {
                    glm::dvec3 co[4], cd[4];
                    cam.ray(x0, y0, co[0], cd[0]);
                    cam.ray(x1, y0, co[1], cd[1]);
                    cam.ray(x1, y1, co[2], cd[2]);
                    cam.ray(x0, y1, co[3], cd[3]);
                    if (render::tile_misses_box(f.reach, co, cd)) {
                        c.primary += std::uint64_t(x1 - x0) * std::uint64_t(y1 - y0);
                        continue;
                    }
                }
                for (int y = y0; y < y1; ++y)
                    for (int x = x0; x < x1; ++x) trace_pixel(f, cam, lights, x, y, ctx, c);
            }
            primary += c.primary;
            shadow += c.shadow;
        });
    });
    return {primary.load(), shadow.load()};
}

struct Run {
    double seconds = 0, build = 0;
    Counts rays;
    double per_core(int threads) const { return double(rays.rays()) / seconds / threads * 1e-6; }
};

Run floor_run(const csg::Scene& s, int size, int threads, bool native) {
    tbb::task_arena arena(threads);
    const auto t0 = std::chrono::steady_clock::now();
    Floor f;
    arena.execute([&] { build(f, s, native); });
    const auto t1 = std::chrono::steady_clock::now();
    Run r;
    r.rays = trace_image(f, s, size, arena);
    const auto t2 = std::chrono::steady_clock::now();
    r.build = std::chrono::duration<double>(t1 - t0).count();
    r.seconds = std::chrono::duration<double>(t2 - t0).count();  // build + trace, as kerf's render time
    static bool told = false;
    if (!told) {
        std::printf("floor leaves: %zu native spheres, %zu user geometry, %zu triangles, %zu skipped (planes, prisms, lathes)\n",
                    f.sphere_leaf.size(), f.user_leaf.size(), f.triangles, f.skipped);
        told = true;
    }
    return r;
}

Run kerf_run(const csg::Scene& s, int size, int threads) {
    render::RenderOptions o;
    o.width = o.height = size;
    o.spp = 1;          // --aa off
    o.threads = threads;
    o.srgb8 = true;     // what an 8-bit output renders
    render::RenderStats st;
    render::render(s, o, &st);
    Run r;
    r.seconds = st.seconds;
    r.rays = {st.primary_rays, st.shadow_rays + st.reflect_rays + st.refract_rays};
    return r;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_floor SCENE.sdl [size=1024] [threads=1] [runs=5]\n");
        return 2;
    }
    const std::string path = argv[1];
    const int size = argc > 2 ? std::atoi(argv[2]) : 1024;
    const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
    const int runs = argc > 4 ? std::atoi(argv[4]) : 5;
    try {
        EvalOptions eval;
        eval.limits.primitives = 2000000;
        const EvalResult evaluated = evaluate_file(path, eval);
        const csg::Scene scene = lower_to_csg(evaluated.graph, LowerOptions{Look::Studio, 1.0});
        std::printf("%s: %zu leaves, %zu lights, %dx%d, %d thread(s)\n", path.c_str(), scene.leaves.size(),
                    scene.lights.size(), size, size, threads);
        std::vector<double> kerf_rate, native_rate, user_rate, tax, tax_user, time_ratio;
        for (int i = 0; i < runs; ++i) {  // alternating: kerf, floor (native), floor (user geometry only)
            const Run k = kerf_run(scene, size, threads);
            const Run n = floor_run(scene, size, threads, true);
            const Run u = floor_run(scene, size, threads, false);
            std::printf("run %d: kerf %.3f s %llu+%llu rays %.2f MRay/s/core | floor %.3f s (build %.3f) %llu+%llu rays "
                        "%.2f MRay/s/core | user-only floor %.3f s %.2f MRay/s/core\n",
                        i + 1, k.seconds, (unsigned long long)k.rays.primary, (unsigned long long)k.rays.shadow,
                        k.per_core(threads), n.seconds, n.build, (unsigned long long)n.rays.primary,
                        (unsigned long long)n.rays.shadow, n.per_core(threads), u.seconds, u.per_core(threads));
            kerf_rate.push_back(k.per_core(threads));
            native_rate.push_back(n.per_core(threads));
            user_rate.push_back(u.per_core(threads));
            tax.push_back(n.per_core(threads) / k.per_core(threads));
            tax_user.push_back(u.per_core(threads) / k.per_core(threads));
            time_ratio.push_back(k.seconds / n.seconds);
        }
        std::printf("summary: kerf %.3f floor %.3f user_floor %.3f tax %.2f user_tax %.2f time %.2f (MRay/s/core "
                    "medians; tax = median of per-run floor/kerf rates; time = median of per-run kerf/floor seconds)\n",
                    median(kerf_rate), median(native_rate), median(user_rate), median(tax), median(tax_user),
                    median(time_ratio));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_floor: %s\n", e.what());
        return 1;
    }
}
