#include "csg/dump.hpp"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

namespace kerf::csg {

namespace {

// 6 significant digits, "inf"/"-inf", and no "-0": the same scene prints the
// same text on every platform.
void num(std::string& out, double v) {
    if (v == 0) v = 0;  // drops the sign of -0
    char buf[32];
    if (std::isinf(v)) std::snprintf(buf, sizeof buf, "%s", v > 0 ? "inf" : "-inf");
    else if (std::isnan(v)) std::snprintf(buf, sizeof buf, "nan");
    else std::snprintf(buf, sizeof buf, "%.6g", v);
    out += buf;
}

void vec(std::string& out, const glm::dvec3& v) {
    out += '[';
    for (int i = 0; i < 3; ++i) {
        if (i) out += ' ';
        num(out, v[i]);
    }
    out += ']';
}

void field(std::string& out, const char* name, double v) {
    out += ' ';
    out += name;
    out += '=';
    num(out, v);
}

void field(std::string& out, const char* name, const glm::dvec3& v) {
    out += ' ';
    out += name;
    out += '=';
    vec(out, v);
}

void bounds(std::string& out, const Aabb& b) {
    if (b.empty()) {
        out += " bounds=empty";
        return;
    }
    field(out, "lo", b.lo);
    field(out, "hi", b.hi);
}

const char* op_name(Op op) {
    switch (op) {
        case Op::Leaf: return "leaf";
        case Op::Union: return "union";
        case Op::Intersection: return "intersection";
        case Op::Difference: return "difference";
    }
    return "?";
}

void leaf_shape(std::string& out, const Leaf& l) {
    const double* p = l.p;
    switch (l.kind) {
        case PrimKind::Sphere: out += "sphere"; field(out, "r", p[0]); break;
        case PrimKind::Box:
            out += "box";
            field(out, "min", glm::dvec3(p[0], p[1], p[2]));
            field(out, "max", glm::dvec3(p[3], p[4], p[5]));
            break;
        case PrimKind::Cylinder:
            out += "cylinder";
            field(out, "z0", p[0]); field(out, "z1", p[1]);
            field(out, "r0", p[2]); field(out, "r1", p[3]);
            break;
        case PrimKind::Torus: out += "torus"; field(out, "R", p[0]); field(out, "r", p[1]); break;
        case PrimKind::Plane:
            out += "plane";
            field(out, "normal", glm::dvec3(p[0], p[1], p[2]));
            field(out, "offset", p[3]);
            break;
        case PrimKind::Paraboloid: out += "paraboloid"; field(out, "h", p[0]); field(out, "r", p[1]); break;
        case PrimKind::Hyperboloid:
            out += "hyperboloid";
            field(out, "h", p[0]); field(out, "r", p[1]); field(out, "waist", p[2]);
            break;
        case PrimKind::Mesh: out += "mesh mesh=" + std::to_string(l.mesh); break;
        case PrimKind::Prism:
            out += "prism polygon=" + std::to_string(l.polygon);
            field(out, "z0", p[0]); field(out, "z1", p[1]);
            if (p[2] != 0 || p[3] != 0) field(out, "top_scale", 1 + p[2]);
            if (p[3] != 0) field(out, "top_scale_y", 1 + p[2] + p[3]);
            if (p[4] != 0) field(out, "twist", p[4] * 180 / 3.14159265358979323846);
            break;
        case PrimKind::Lathe: out += "lathe polygon=" + std::to_string(l.polygon); break;
    }
}

void leaf_line(std::string& out, const Scene& s, std::uint32_t index) {
    const Leaf& l = s.leaves[index];
    leaf_shape(out, l);
    out += " leaf=" + std::to_string(index);
    out += " material=" + std::to_string(l.material);
    bounds(out, l.bounds);
    // world_from_object as three rows [linear | offset]
    out += " world=[";
    for (int r = 0; r < 3; ++r) {
        if (r) out += " | ";
        for (int c = 0; c < 3; ++c) {
            num(out, l.world_from_object.linear[c][r]);
            out += ' ';
        }
        num(out, l.world_from_object.offset[r]);
    }
    out += ']';
    out += " at=";
    if (l.source < s.sources.size()) {
        const SourceRef& src = s.sources[l.source];
        out += src.file < s.files.size() ? s.files[src.file] : std::string("?");
        out += ':' + std::to_string(src.line) + ':' + std::to_string(src.col);
    } else {
        out += '?';
    }
}

// `flush` hands over the text so far (the tree of a million-leaf scene is
// hundreds of MB: streamed, it never has to exist as one string).
template <typename Flush>
void tree(std::string& out, const Scene& s, Flush&& flush) {
    if (s.root == kNone || s.root >= s.nodes.size()) {
        out += "tree empty\n";
        return;
    }
    out += "tree\n";
    struct Item { std::uint32_t node, depth; };
    std::vector<Item> stack{{s.root, 0}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        const Node& n = s.nodes[it.node];
        if (out.size() > (1u << 16)) flush(out);
        out.append(2 * it.depth, ' ');
        if (n.op == Op::Leaf) {
            if (n.first < s.leaves.size()) leaf_line(out, s, n.first);
            else out += "leaf ?";
            out += '\n';
            continue;
        }
        out += op_name(n.op);
        out += " children=" + std::to_string(n.count);
        bounds(out, n.bounds);
        out += '\n';
        for (std::uint32_t k = n.count; k-- > 0;) {
            const std::size_t ref = std::size_t(n.first) + k;
            if (ref < s.children.size() && s.children[ref] < s.nodes.size())
                stack.push_back({s.children[ref], it.depth + 1});
        }
    }
}

// The materials, meshes and tree of a scene (the solid's or a ghost's).
template <typename Flush>
void body(const Scene& s, std::string& out, Flush&& flush) {
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const Material& m = s.materials[i];
        out += "material " + std::to_string(i);
        field(out, "color", m.color);
        field(out, "interior", m.interior);
        field(out, "diffuse", m.diffuse);
        field(out, "specular", m.specular);
        field(out, "shininess", m.shininess);
        field(out, "reflect", m.reflect);
        // The glass and glow fields only where they differ from an opaque material.
        if (m.transparency != 0) field(out, "transparency", m.transparency);
        if (m.ior != 1) field(out, "ior", m.ior);
        if (m.absorption != glm::dvec3(0)) field(out, "absorption", m.absorption);
        if (m.roughness != 0) field(out, "roughness", m.roughness);
        if (m.emission != glm::dvec3(0)) field(out, "emission", m.emission);
        if (m.pattern != Pattern::None) {
            static const char* const kNames[] = {"none", "checker", "stripes", "gradient", "noise", "marble", "wood", "image"};
            out += std::string(" pattern=") + kNames[static_cast<int>(m.pattern)];
            if (m.texture) {
                static const char* const kMappings[] = {"planar", "spherical", "cylindrical"};
                out += " texture=" + m.texture->path + " mapping=" + kMappings[static_cast<int>(m.mapping)] +
                       (m.bilinear ? " bilinear" : " nearest");
            } else {
                field(out, "color2", m.color2);
            }
        }
        out += '\n';
    }
    for (std::size_t i = 0; i < s.meshes.size(); ++i) {
        const Mesh& m = s.meshes[i];
        out += "mesh " + std::to_string(i) + " points=" + std::to_string(m.points.size()) +
               " triangles=" + std::to_string(m.triangles.size() / 3) + (m.solid ? " solid\n" : " shell\n");
    }
    tree(out, s, flush);
}

template <typename Flush>
void dump(const Scene& s, std::string& out, Flush&& flush) {
    out += "kerf-dump 1\n";
    out += "scene leaves=" + std::to_string(s.leaves.size()) + " nodes=" + std::to_string(s.nodes.size()) +
           " materials=" + std::to_string(s.materials.size()) + " meshes=" + std::to_string(s.meshes.size()) + '\n';
    const Camera& c = s.camera;
    out += c.orthographic                               ? "camera orthographic"
           : c.projection == Projection::Fisheye   ? "camera fisheye"
           : c.projection == Projection::Panoramic ? "camera panoramic"
                                                   : "camera perspective";
    field(out, "position", c.position);
    field(out, "look_at", c.look_at);
    field(out, "up", c.up);
    if (c.orthographic) field(out, "height", c.height); else field(out, "fov", c.fov);
    // Depth of field only where it is on, so pinhole dumps read as before.
    if (c.aperture > 0) {
        field(out, "aperture", c.aperture);
        field(out, "focal_distance", c.focal_distance);
        field(out, "blur_samples", double(c.blur_samples));
    }
    out += '\n';
    for (const Light& l : s.lights) {
        if (l.directional) {
            out += "light distant";
            field(out, "direction", l.direction);
        } else {
            out += l.spot ? "light spot" : "light point";
            field(out, "position", l.position);
            if (l.spot) {
                field(out, "direction", l.direction);
                field(out, "angle", l.spot_angle);
                field(out, "falloff", l.spot_falloff);
            }
        }
        field(out, "color", l.color);
        field(out, "intensity", l.intensity);
        // Only what differs from a plain light, so older dumps still read the same.
        if (l.radius > 0) {
            field(out, "radius", l.radius);
            field(out, "samples", double(l.samples));
            if (l.probe) out += " probe=5";
        }
        if (!l.shadows) out += " shadows=false";
        if (l.inverse_square) out += " attenuation=inverse_square";
        out += '\n';
    }
    out += "background";
    field(out, "color", s.background);
    out += '\n';
    if (s.ground.on) {  // the studio look's shadow catcher: no solid, so not in the tree
        out += "ground";
        field(out, "z", s.ground.z);
        field(out, "shadow", s.ground.shadow);
        out += '\n';
    }
    if (s.fog.on()) {
        out += "fog";
        field(out, "distance", s.fog.distance);
        field(out, "color", s.fog.color);
        out += '\n';
    }
    body(s, out, flush);
    // The ghosts after the solid, each marked by its own header line: what
    // follows it, up to the next header, is that ghost's own materials,
    // meshes and tree (their indices its own), as the renderer receives them.
    for (const Scene& g : s.ghosts) {
        out += g.ghost_kind == GhostKind::Highlight ? "ghost highlight" : "ghost background";
        out += " leaves=" + std::to_string(g.leaves.size()) + " nodes=" + std::to_string(g.nodes.size()) +
               " materials=" + std::to_string(g.materials.size()) + " meshes=" + std::to_string(g.meshes.size()) + '\n';
        body(g, out, flush);
    }
}

}  // namespace

std::string dump_scene(const Scene& s) {
    std::string out;
    dump(s, out, [](std::string&) {});
    return out;
}

void dump_scene(const Scene& s, std::ostream& os) {
    std::string buf;
    auto flush = [&os](std::string& text) {
        os.write(text.data(), static_cast<std::streamsize>(text.size()));
        text.clear();
    };
    dump(s, buf, flush);
    flush(buf);
}

}  // namespace kerf::csg
