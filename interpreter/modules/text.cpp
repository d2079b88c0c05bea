// text(): OpenSCAD's text module as 2D shapes, one Prism per glyph over its
// flattened outline (interpreter/text/ shapes and places the glyphs),
// united, carried flat like the other 2D shapes (shapes2d.cpp).
#include <stdexcept>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/text/font.hpp"
#include "interpreter/text/layout.hpp"

namespace kerf::eval {

namespace {

enum Param { Text, Size, Font, Halign, Valign, Spacing, Direction, Language, Script };

std::string arg_string(const Args& a, std::size_t i, const char* name, std::string fallback) {
    if (!a.has(i) || a[i].is_undef()) return fallback;
    if (!a[i].is_string()) arg_error(a, std::string(name) + " must be a string, got " + to_repr(a[i]));
    return a[i].as_string();
}

// One of `allowed`, else an error; in the OpenSCAD dialect a warning and
// the first (OpenSCAD's default), as OpenSCAD does.
std::string arg_choice(ModuleCall& c, std::size_t i, const char* name, std::initializer_list<const char*> allowed) {
    std::string v = arg_string(c.args, i, name, "");
    if (v.empty() && i != Direction) return *allowed.begin();
    if (v.empty()) return v;
    std::string list;
    for (const char* s : allowed) {
        if (v == s) return v;
        list += std::string(list.empty() ? "" : ", ") + '"' + s + '"';
    }
    const std::string message = std::string(name) + " must be one of " + list + ", got \"" + v + "\"";
    if (!c.lenient()) arg_error(c.args, message);
    c.warn(message + "; using " + (i == Direction ? std::string("the script's direction")
                                                 : '"' + std::string(*allowed.begin()) + '"'));
    return i == Direction ? std::string() : *allowed.begin();
}

void text(ModuleCall& c) {
    const Args& a = c.args;
    text::TextParams p;
    if (!a.has(Text) || a[Text].is_undef()) arg_error(a, "text must be a string, got undef");
    p.text = arg_string(a, Text, "text", "");
    p.size = arg_positive(a, Size, "size", 10);
    p.font = arg_string(a, Font, "font", "");
    p.halign = arg_choice(c, Halign, "halign", {"left", "center", "right"});
    p.valign = arg_choice(c, Valign, "valign", {"baseline", "top", "center", "bottom"});
    p.spacing = arg_number(a, Spacing, "spacing", 1);
    p.direction = arg_choice(c, Direction, "direction", {"ltr", "rtl", "ttb", "btt"});
    p.language = arg_string(a, Language, "language", "en");
    p.script = arg_string(a, Script, "script", "");
    p.tolerance = c.curve_tolerance();
    c.exact_curve();  // the outlines are flattened to the tolerance, not in OpenSCAD's $fn steps
    p.fallback_font = c.lenient();
    text::TextShape shape;
    try {
        shape = text::layout_text(p);
    } catch (const text::FontNameError& e) {
        // OpenSCAD 2021.01 accepts such a name and crashes drawing it (a
        // segmentation fault, measured); its test data
        // 2D/features/text-font-charset.scad expects a warning and no text.
        if (!c.lenient()) throw SourceError(c.st.loc, std::string("text: ") + e.what());
        c.warn(std::string(e.what()) + "; nothing drawn");
    } catch (const text::FontError& e) {
        throw SourceError(c.st.loc, std::string("text: ") + e.what());  // not soft: the model would be wrong
    } catch (const std::invalid_argument& e) {
        arg_error(a, e.what());
    }
    for (std::string& w : shape.warnings) c.warn(std::move(w));
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    for (csg::Polygon2& glyph : shape.glyphs) {
        g.graph.polygons.push_back(std::move(glyph));
        c.add_primitive(csg::PrimKind::Prism, {0, 1}, static_cast<std::uint32_t>(g.graph.polygons.size() - 1));
        g.graph.nodes[g.pending.back()].flat = true;
    }
    g.group(mark, c.st.loc);
}

const ModuleEntry kText[] = {
    {"text", ModuleKind::Solid,
     {"text", "size", "font", "halign", "valign", "spacing", "direction", "language", "script"}, text},
};

}  // namespace

std::span<const ModuleEntry> text_modules() { return kText; }

}  // namespace kerf::eval
