#include "cli/farm_key.hpp"

#include <cstdio>
#include <cstring>
#include <sstream>

namespace kerf::cli {

namespace {

// FNV-1a over values, never over struct bytes (padding is not data).
struct Hasher {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void bytes(const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
    }
    void u(std::uint64_t v) { bytes(&v, sizeof v); }
    void d(double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        u(bits);
    }
    void v3(const glm::dvec3& v) { d(v.x), d(v.y), d(v.z); }
    void m3(const glm::dmat3& m) { v3(m[0]), v3(m[1]), v3(m[2]); }
    void box(const csg::Aabb& b) { v3(b.lo), v3(b.hi); }
    void affine(const csg::Affine& a) { m3(a.linear), v3(a.offset); }
};

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

}  // namespace

std::uint64_t scene_hash(const csg::Scene& s) {
    Hasher h;
    h.u(s.leaves.size());
    for (const csg::Leaf& l : s.leaves) {
        h.u(std::uint64_t(l.kind)), h.u(l.material), h.u(l.mesh), h.u(l.polygon);
        for (double p : l.p) h.d(p);
        h.affine(l.object_from_world), h.affine(l.world_from_object), h.box(l.bounds);
        h.u(l.material_frame);
    }
    h.u(s.material_frames.size());
    for (const csg::Affine& f : s.material_frames) h.affine(f);
    h.u(s.nodes.size());
    for (const csg::Node& n : s.nodes) h.u(std::uint64_t(n.op)), h.u(n.first), h.u(n.count), h.u(n.parent), h.box(n.bounds);
    h.u(s.children.size());
    for (std::uint32_t c : s.children) h.u(c);
    h.u(s.root);
    h.u(s.materials.size());
    for (const csg::Material& m : s.materials)
        h.v3(m.color), h.v3(m.interior), h.d(m.diffuse), h.d(m.specular), h.d(m.shininess), h.d(m.reflect),
            h.d(m.transparency), h.d(m.ior), h.v3(m.absorption), h.d(m.roughness), h.v3(m.emission),
            h.u(std::uint64_t(m.pattern)), h.v3(m.color2), h.affine(m.pattern_from_material),
            h.u(m.texture ? m.texture->digest : 0), h.u(std::uint64_t(m.mapping)), h.u(m.bilinear);
    h.u(s.meshes.size());
    for (const csg::Mesh& m : s.meshes) {
        h.u(m.points.size()), h.u(m.triangles.size()), h.u(m.solid);
        for (const auto& p : m.points) h.v3(p);
        for (std::uint32_t t : m.triangles) h.u(t);
    }
    h.u(s.polygons.size());
    for (const csg::Polygon2& p : s.polygons) {
        h.u(p.edges.size());
        for (const auto& e : p.edges) h.d(e.x), h.d(e.y), h.d(e.z), h.d(e.w);
    }
    const csg::Camera& c = s.camera;
    h.v3(c.position), h.v3(c.look_at), h.v3(c.up), h.d(c.fov), h.u(c.orthographic), h.d(c.height);
    h.u(std::uint64_t(c.projection)), h.d(c.aperture), h.d(c.focal_distance), h.u(c.blur_samples);
    h.u(s.lights.size());
    for (const csg::Light& l : s.lights) h.u(l.directional), h.v3(l.position), h.v3(l.direction), h.v3(l.color), h.d(l.intensity);
    h.v3(s.background);
    h.u(std::uint64_t(s.ambient_occlusion.samples)), h.d(s.ambient_occlusion.distance);
    h.d(s.fog.distance), h.v3(s.fog.color);
    h.u(s.ground.on), h.d(s.ground.z), h.d(s.ground.shadow);
    for (const csg::Light& l : s.lights)
        h.d(l.radius), h.u(l.samples), h.u(l.shadows), h.u(l.inverse_square), h.u(l.spot), h.d(l.spot_angle), h.d(l.spot_falloff);
    // The `%` and `#` ghosts (or none, --no-ghosts) change the pixels too.
    h.u(s.ghosts.size());
    for (const csg::Scene& ghost : s.ghosts) h.u(scene_hash(ghost));
    return h.h;
}

std::string render_key(const csg::Scene& scene, const render::RenderOptions& ro, FacetMode facets) {
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(scene_hash(scene)));
    std::string options = ro.adaptive ? "aa:" + std::to_string(ro.aa_samples) + ":" + number(ro.aa_threshold)
                                      : "spp:" + std::to_string(ro.spp);
    if (ro.preview) options += ",preview";
    if (ro.aov != render::Aov::None) options += ",aov:" + std::to_string(int(ro.aov));
    options += ro.double_precision ? ",double" : ",float";
    options += ",reflect:" + std::to_string(ro.max_reflect_depth);
    if (facets != FacetMode::Auto) options += facets == FacetMode::Exact ? ",facets:exact" : ",facets:openscad";
    if (ro.integrator == render::Integrator::Path) options += ",path:" + std::to_string(ro.max_path_depth);
    if (ro.crop) {
        const auto& k = *ro.crop;
        options += ",crop:" + std::to_string(k[0]) + ":" + std::to_string(k[1]) + ":" + std::to_string(k[2]) + ":" +
                   std::to_string(k[3]);
    }
    return std::string("scene=") + hash + " width=" + std::to_string(ro.width) + " height=" +
           std::to_string(ro.height) + " seed=" + std::to_string(ro.seed) + " options=" + options;
}

std::map<std::string, std::string> parse_key(const std::string& text) {
    std::map<std::string, std::string> out;
    std::istringstream words(text);
    for (std::string w; words >> w;)
        if (const std::size_t eq = w.find('='); eq != std::string::npos) out[w.substr(0, eq)] = w.substr(eq + 1);
    return out;
}

}  // namespace kerf::cli
