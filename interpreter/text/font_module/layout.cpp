// layout_text: shaping (HarfBuzz over FreeType), OpenSCAD 2021.01's
// placement rules, and the outlines flattened within the tolerance
// (chords.cpp), in the font module (font_module.hpp).
#include "interpreter/text/layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include <hb-ft.h>
#include <hb.h>

#include "interpreter/text/font.hpp"
#include "interpreter/text/font_module/font_module.hpp"

namespace kerf::text {

namespace {

// OpenSCAD sets the character size to size · 1000 (26.6 points) at 100 dpi
// and divides outline coordinates by 1000, so the em is size · 100/72. It
// divides HarfBuzz's positions by 1024 instead (64 · 16), so advances and
// offsets come out 1000/1024 of the outline's scale: kept, so that a line
// of text lines up with OpenSCAD 2021's (newer OpenSCAD divides both by
// 1000; docs/openscad.md).
constexpr double kReferenceSize = 10;
constexpr double kPositionScale = 1.0 / 1024.0;
struct Outliner {
    glm::dvec2 origin{0};
    double scale = 1;  // font units -> kerf units
    double tol = 0;
    csg::Polygon2 poly;
    glm::dvec2 at{0};

    glm::dvec2 map(const FT_Vector* v) const {
        return origin + scale * glm::dvec2(static_cast<double>(v->x), static_cast<double>(v->y));
    }
    void edge(const glm::dvec2& q) {
        if (q != at) {
            poly.edges.emplace_back(at.x, at.y, q.x, q.y);
            poly.lo = glm::min(poly.lo, glm::min(at, q));
            poly.hi = glm::max(poly.hi, glm::max(at, q));
        }
        at = q;
    }
    static Outliner& of(void* user) { return *static_cast<Outliner*>(user); }
    static int move_to(const FT_Vector* to, void* user) {
        of(user).at = of(user).map(to);
        return 0;
    }
    static int line_to(const FT_Vector* to, void* user) {
        of(user).edge(of(user).map(to));
        return 0;
    }
    static int conic_to(const FT_Vector* c, const FT_Vector* to, void* user) {
        Outliner& o = of(user);
        const glm::dvec2 p0 = o.at, p1 = o.map(c), p2 = o.map(to);
        const int n = quadratic_chords(p0, p1, p2, o.tol);
        for (int i = 1; i <= n; ++i) {
            const double t = static_cast<double>(i) / n, s = 1 - t;
            o.edge(i == n ? p2 : s * s * p0 + 2 * s * t * p1 + t * t * p2);
        }
        return 0;
    }
    static int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
        Outliner& o = of(user);
        const glm::dvec2 p0 = o.at, p1 = o.map(c1), p2 = o.map(c2), p3 = o.map(to);
        const int n = cubic_chords(p0, p1, p2, p3, o.tol);
        for (int i = 1; i <= n; ++i) {
            const double t = static_cast<double>(i) / n, s = 1 - t;
            o.edge(i == n ? p3 : s * s * s * p0 + 3 * s * s * t * p1 + 3 * s * t * t * p2 + t * t * t * p3);
        }
        return 0;
    }
};

void check_choice(const std::string& value, std::initializer_list<const char*> allowed, const char* name) {
    for (const char* a : allowed)
        if (value == a) return;
    std::string list;
    for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + '"' + a + '"';
    throw std::invalid_argument(std::string(name) + " must be one of " + list + ", got \"" + value + "\"");
}

// HarfBuzz's handles, released on every path.
struct Shaped {
    hb_font_t* font = nullptr;
    hb_buffer_t* buffer = nullptr;
    ~Shaped() {
        if (buffer) hb_buffer_destroy(buffer);
        if (font) hb_font_destroy(font);
    }
};

}  // namespace

TextShape module_layout_text(const TextParams& p) {
    if (!(p.size > 0) || !std::isfinite(p.size))
        throw std::invalid_argument("size must be a positive number, got " + std::to_string(p.size));
    if (!std::isfinite(p.spacing)) throw std::invalid_argument("spacing must be a finite number");
    if (!(p.tolerance > 0)) throw std::invalid_argument("the curve tolerance must be positive");
    check_choice(p.halign, {"left", "center", "right"}, "halign");
    check_choice(p.valign, {"baseline", "top", "center", "bottom"}, "valign");
    if (!p.direction.empty()) check_choice(p.direction, {"ltr", "rtl", "ttb", "btt"}, "direction");

    TextShape out;
    std::string substitute;
    Font font = module_find_font(p.font, p.fallback_font, &substitute);
    if (!substitute.empty())
        out.warnings.push_back("font '" + p.font + "' is not installed; using '" + substitute + "'");
    if (p.text.empty()) return out;

    // The face is shared by every text() of the run: one layout at a time.
    static std::mutex mutex;
    std::lock_guard lock(mutex);
    FT_Face face = font.face;
    if (FT_Set_Char_Size(face, 0, static_cast<FT_F26Dot6>(kReferenceSize * 1000), 100, 100) != 0)
        throw std::invalid_argument("the font '" + font.family + "' cannot be scaled");
    Shaped hb;
    hb.font = hb_ft_font_create(face, nullptr);
    hb_ft_font_set_load_flags(hb.font, FT_LOAD_DEFAULT | FT_LOAD_NO_HINTING);
    hb.buffer = hb_buffer_create();
    hb_buffer_add_utf8(hb.buffer, p.text.data(), static_cast<int>(p.text.size()), 0, static_cast<int>(p.text.size()));
    if (!p.direction.empty()) hb_buffer_set_direction(hb.buffer, hb_direction_from_string(p.direction.c_str(), -1));
    if (!p.script.empty()) {
        const hb_script_t script = hb_script_from_string(p.script.c_str(), -1);
        if (script == HB_SCRIPT_INVALID || script == HB_SCRIPT_UNKNOWN)
            throw std::invalid_argument("script \"" + p.script + "\" is not an ISO 15924 script name");
        hb_buffer_set_script(hb.buffer, script);
    }
    hb_buffer_set_language(hb.buffer, hb_language_from_string(p.language.c_str(), -1));
    hb_buffer_guess_segment_properties(hb.buffer);
    hb_shape(hb.font, hb.buffer, nullptr, 0);
    unsigned count = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(hb.buffer, &count);
    const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(hb.buffer, &count);
    const bool horizontal = HB_DIRECTION_IS_HORIZONTAL(hb_buffer_get_direction(hb.buffer));

    const double outline_scale = p.size * 100.0 / 72.0 / face->units_per_EM;  // font units -> kerf
    const double position_scale = kPositionScale * p.size / kReferenceSize;   // 26.6 -> kerf
    const double box_scale = outline_scale * 1000.0 / 1024.0;                  // OpenSCAD's /1024 of the box
    FT_Outline_Funcs funcs{};
    funcs.move_to = &Outliner::move_to;
    funcs.line_to = &Outliner::line_to;
    funcs.conic_to = &Outliner::conic_to;
    funcs.cubic_to = &Outliner::cubic_to;
    // Each glyph is loaded once: its box feeds the alignment, its outline is
    // flattened at the pen, and the alignment shifts every glyph after.
    double width = 0, ascend = 0, descend = 0;
    glm::dvec2 pen(0);
    for (unsigned i = 0; i < count; ++i) {
        const FT_UInt index = info[i].codepoint;
        if (FT_Load_Glyph(face, index, FT_LOAD_NO_SCALE) != 0 || face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
            throw std::invalid_argument("the font '" + font.family + "' has no outline for glyph " + std::to_string(index));
        FT_BBox b;
        FT_Outline_Get_CBox(&face->glyph->outline, &b);
        if (face->glyph->outline.n_points == 0) b = FT_BBox{0, 0, 0, 0};
        if (horizontal) {
            width += pos[i].x_advance * position_scale * p.spacing;
            ascend = std::max(ascend, std::max(0.0, b.yMax * box_scale));
            descend = std::max(descend, std::max(0.0, -b.yMin * box_scale));
        } else {
            width = std::max(width, (b.xMax - b.xMin) * box_scale);
            ascend += pos[i].y_advance * position_scale * p.spacing;
        }
        Outliner o;
        o.origin = pen + position_scale * glm::dvec2(static_cast<double>(pos[i].x_offset),
                                                     static_cast<double>(pos[i].y_offset));
        o.scale = outline_scale;
        o.tol = p.tolerance * p.size;
        o.poly.lo = glm::dvec2(std::numeric_limits<double>::infinity());
        o.poly.hi = -o.poly.lo;
        pen += p.spacing * position_scale *
               glm::dvec2(static_cast<double>(pos[i].x_advance), static_cast<double>(pos[i].y_advance));
        if (FT_Outline_Decompose(&face->glyph->outline, &funcs, &o) != 0)
            throw std::invalid_argument("the outline of glyph " + std::to_string(index) + " of '" + font.family +
                                        "' is malformed");
        if (!o.poly.edges.empty()) out.glyphs.push_back(std::move(o.poly));
    }
    const glm::dvec2 shift(p.halign == "right" ? -width : p.halign == "center" ? -width / 2 : 0,
                           p.valign == "top"      ? -ascend
                           : p.valign == "center" ? descend / 2 - ascend / 2
                           : p.valign == "bottom" ? descend
                                                  : 0);
    if (shift != glm::dvec2(0))
        for (csg::Polygon2& g : out.glyphs) {
            for (glm::dvec4& e : g.edges) e += glm::dvec4(shift, shift);
            g.lo += shift, g.hi += shift;
        }
    return out;
}

}  // namespace kerf::text
