// color() and material() (docs/spec.md §5).
#include <cmath>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {
double unit_interval(const Args& a, std::size_t i, const char* name, double fallback) {
    double x = arg_number(a, i, name, fallback);
    if (x < 0 || x > 1) arg_error(a, std::string(name) + " must be in [0, 1], got " + format_number(x));
    return x;
}
using CurrentMaterial = ModuleState::CurrentMaterial;

// An inner color() or material() starts from the enclosing material, so
// `material(specular = 1) color("red") sphere();` keeps the specular.

// A colour's alpha is its transparency: alpha 1 opaque, 0 clear glass.
void set_color(CurrentMaterial& cur, const glm::dvec4& col) {
    cur.m.color = glm::dvec3(col);
    cur.m.transparency = 1 - col.a;
    if (!cur.interior_set) cur.m.interior = cur.m.color;
}

double non_negative(const Args& a, std::size_t i, const char* name, double fallback) {
    double x = arg_number(a, i, name, fallback);
    if (x < 0) arg_error(a, std::string(name) + " must not be negative, got " + format_number(x));
    return x;
}

// absorption: one coefficient for all channels or [r, g, b], each >= 0 and
// per unit length (light crossing d units keeps exp(-absorption·d)).
glm::dvec3 absorption(const Args& a, std::size_t i, glm::dvec3 fallback) {
    if (!a.has(i)) return fallback;
    if (a[i].is_number()) return glm::dvec3(non_negative(a, i, "absorption", 0));
    const glm::dvec3 v = arg_vec3(a, i, "absorption", fallback);
    if (v.x < 0 || v.y < 0 || v.z < 0) arg_error(a, "absorption must not be negative");
    return v;
}

// emission: a number scales the material's colour, a colour is used as it is.
glm::dvec3 emission(const Args& a, std::size_t i, const CurrentMaterial& cur) {
    if (!a.has(i)) return cur.m.emission;
    if (a[i].is_number()) return non_negative(a, i, "emission", 0) * cur.m.color;
    return glm::dvec3(arg_color(a, i, "emission"));
}

struct PatternName {
    const char* name;
    csg::Pattern pattern;
};
constexpr PatternName kPatterns[] = {{"none", csg::Pattern::None},         {"checker", csg::Pattern::Checker},
                                     {"stripes", csg::Pattern::Stripes},   {"gradient", csg::Pattern::Gradient},
                                     {"noise", csg::Pattern::Noise},       {"marble", csg::Pattern::Marble},
                                     {"wood", csg::Pattern::Wood}};

csg::Pattern pattern_kind(const Args& a, std::size_t i, csg::Pattern fallback) {
    if (!a.has(i)) return fallback;
    std::string names;
    for (const PatternName& p : kPatterns) {
        if (a[i].is_string() && a[i].as_string() == p.name) return p.pattern;
        names += std::string(names.empty() ? "" : ", ") + '"' + p.name + '"';
    }
    if (!a[i].is_string()) arg_error(a, "pattern must be a string, one of " + names);
    arg_error(a, "unknown pattern \"" + a[i].as_string() + "\" (one of " + names + ")");
}

// pattern, color2, pattern_scale, pattern_transform (docs/language.md,
// "Patterns"). The pattern's coordinates are those of this call, mapped by
// the inverse of pattern_transform and then divided by pattern_scale, so a
// larger scale or a scaling transform makes the cells larger.
void read_pattern(ModuleCall& c, CurrentMaterial& cur) {
    const Args& a = c.args;
    cur.m.pattern = pattern_kind(a, 12, cur.m.pattern);
    if (a.has(11)) {
        cur.m.color2 = glm::dvec3(arg_color(a, 11, "color2"));
        cur.color2_set = true;
    }
    if (a.has(13) || a.has(14)) {
        const double scale = arg_number(a, 13, "pattern_scale", 1);
        if (!(scale > 0)) arg_error(a, "pattern_scale must be positive, got " + format_number(scale));
        const glm::dmat4 m = a.has(14) ? arg_matrix(a, 14, "pattern_transform") : glm::dmat4(1.0);
        const glm::dmat3 l(m);
        if (!(std::abs(glm::determinant(l)) > 1e-300)) arg_error(a, "pattern_transform must be invertible");
        // A new scale or transform replaces the enclosing material's.
        const glm::dmat3 inv = glm::inverse(l) / scale;
        cur.m.pattern_from_material = csg::Affine{inv, -(inv * glm::dvec3(m[3]))};
    }
    if (!(a.has(12) || a.has(13) || a.has(14))) return;
    if (cur.m.pattern == csg::Pattern::Image || a.has(15)) return;  // an image needs no color2
    if (cur.m.pattern == csg::Pattern::None) {
        if (a.has(13) || a.has(14)) c.warn("pattern_scale and pattern_transform are ignored without a pattern");
    } else if (!cur.color2_set) {
        c.warn("a pattern without color2 blends color with black (give color2)");
    }
}

struct MappingName {
    const char* name;
    csg::TextureMapping mapping;
};
constexpr MappingName kMappings[] = {{"planar", csg::TextureMapping::Planar},
                                     {"spherical", csg::TextureMapping::Spherical},
                                     {"cylindrical", csg::TextureMapping::Cylindrical}};

// texture, mapping, interpolation (docs/language.md, "Image textures"): the
// file is read here, once per file (render::read_texture keeps it), so a
// missing or unreadable image is an error at this call, not at render time.
// The image lies in pattern space, so pattern_scale and pattern_transform
// place it too.
void read_texture(ModuleCall& c, CurrentMaterial& cur) {
    const Args& a = c.args;
    if (a.has(15)) {
        if (!a[15].is_string() || a[15].as_string().empty()) arg_error(a, "texture must be a string naming an image file");
        if (a.has(12)) arg_error(a, "texture and pattern exclude each other (a texture is the colour)");
        const csg::TextureReader reader = csg::texture_reader();
        if (!reader) arg_unsupported(a, "image textures need the renderer (this program reads no images)");
        const std::string path = c.files().resolve(a[15].as_string(), c.st.loc);
        std::string why;
        std::shared_ptr<const csg::Texture> t = reader(path, why);
        if (!t) throw SourceError(c.st.loc, why);
        cur.m.texture = std::move(t);
        cur.m.pattern = csg::Pattern::Image;
    } else if (a.has(12) && cur.m.pattern != csg::Pattern::Image) {
        cur.m.texture.reset();
    }
    if (a.has(16)) {
        std::string names;
        bool found = false;
        for (const MappingName& m : kMappings) {
            if (a[16].is_string() && a[16].as_string() == m.name) cur.m.mapping = m.mapping, found = true;
            names += std::string(names.empty() ? "" : ", ") + '"' + m.name + '"';
        }
        if (!found) arg_error(a, "mapping must be one of " + names);
    }
    if (a.has(17)) {
        const bool ok = a[17].is_string() && (a[17].as_string() == "bilinear" || a[17].as_string() == "nearest");
        if (!ok) arg_error(a, "interpolation must be \"bilinear\" or \"nearest\"");
        cur.m.bilinear = a[17].as_string() == "bilinear";
    }
    if ((a.has(16) || a.has(17)) && cur.m.pattern != csg::Pattern::Image)
        c.warn("mapping and interpolation are ignored without a texture");
}

CurrentMaterial enclosing(ModuleCall& c) {
    auto& stack = c.state().materials;
    return stack.empty() ? CurrentMaterial{} : stack.back();
}

// The children with `cur` as the innermost appearance.
void appear(ModuleCall& c, const CurrentMaterial& cur) {

    GraphBuilder& g = c.graph();
    std::size_t mark = g.mark();
    auto& stack = c.state().materials;
    stack.push_back(cur);
    struct Pop {
        std::vector<CurrentMaterial>& s;
        ~Pop() { s.pop_back(); }
    } pop{stack};
    c.children();
    if (g.mark() == mark) return;
    g.graph.materials.push_back(cur.m);
    g.wrap(mark, graph::NodeKind::Appearance, static_cast<std::uint32_t>(g.graph.materials.size() - 1), c.st.loc);
}

void color(ModuleCall& c) {
    const Args& a = c.args;
    CurrentMaterial cur = enclosing(c);
    // OpenSCAD 2021 (c undef is no c): `color()` leaves its children as they
    // are, silently; `color(alpha = 0.5)` keeps the colour and sets the alpha.
    const bool has_c = a.has(0) && !(c.lenient() && a[0].is_undef());
    if (!has_c && !a.has(1) && c.lenient()) return appear(c, cur);
    if (!has_c && !c.lenient()) arg_error(a, "c is required");
    glm::dvec4 col = has_c ? arg_color(a, 0, "c") : glm::dvec4(cur.m.color, 1);
    if (a.has(1)) col.a = unit_interval(a, 1, "alpha", 1);
    set_color(cur, col);
    appear(c, cur);
}

void material(ModuleCall& c) {
    const Args& a = c.args;
    CurrentMaterial cur = enclosing(c);
    if (a.has(0)) set_color(cur, arg_color(a, 0, "color"));
    if (a.has(1)) {
        cur.m.interior = glm::dvec3(arg_color(a, 1, "interior"));
        cur.interior_set = true;
    }
    cur.m.diffuse = unit_interval(a, 2, "diffuse", cur.m.diffuse);
    cur.m.specular = unit_interval(a, 3, "specular", cur.m.specular);
    cur.m.shininess = arg_number(a, 4, "shininess", cur.m.shininess);
    if (cur.m.shininess < 0) arg_error(a, "shininess must not be negative, got " + format_number(cur.m.shininess));
    cur.m.reflect = unit_interval(a, 5, "reflect", cur.m.reflect);
    cur.m.transparency = unit_interval(a, 6, "transparency", cur.m.transparency);
    cur.m.ior = arg_number(a, 7, "ior", cur.m.ior);
    // ior is the ratio inside/outside (outside is always vacuum, 1); below 1
    // models a bubble. The cap keeps a typo (ior = 15) from passing as glass.
    if (!(cur.m.ior > 0 && cur.m.ior <= 10)) arg_error(a, "ior must be in (0, 10], got " + format_number(cur.m.ior));
    cur.m.absorption = absorption(a, 8, cur.m.absorption);
    cur.m.roughness = unit_interval(a, 9, "roughness", cur.m.roughness);
    cur.m.emission = emission(a, 10, cur);
    read_pattern(c, cur);
    read_texture(c, cur);
    appear(c, cur);
}

const ModuleEntry kAppearance[] = {
    {"color", ModuleKind::Operation, {"c", "alpha"}, color},
    {"material", ModuleKind::Operation, {"color", "interior", "diffuse", "specular", "shininess", "reflect", "transparency", "ior", "absorption",
      "roughness", "emission", "color2", "pattern", "pattern_scale", "pattern_transform", "texture", "mapping", "interpolation"},
     material},
};

}  // namespace

std::span<const ModuleEntry> appearance_modules() { return kAppearance; }

}  // namespace kerf::eval
