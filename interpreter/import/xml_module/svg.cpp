// SVG drawings (svg.hpp): libxml2 builds the tree; this file walks it with
// the current transform, turns each shape element into outlines and maps
// the page to millimetres the way OpenSCAD 2021.01 does. In the XML module
// (xml_module.hpp), on the file's bytes.
#include "interpreter/import/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <optional>

#include <libxml/parser.h>
#include <libxml/tree.h>

#include "interpreter/import/formats.hpp"
#include "interpreter/import/mesh_import.hpp"
#include "interpreter/import/svg_path.hpp"
#include "interpreter/import/xml_module/xml_module.hpp"

namespace kerf::eval {

namespace {

using svg::Chain;

constexpr const char* kSvgNs = "http://www.w3.org/2000/svg";

Map2 translate(glm::dvec2 t) {
    Map2 m(1.0);
    m[2] = glm::dvec3(t, 1);
    return m;
}

Map2 scale(double sx, double sy) {
    Map2 m(1.0);
    m[0][0] = sx, m[1][1] = sy;
    return m;
}

class Walker {
public:
    Walker(const SvgOptions& o, SvgDrawing& out) : o_(o), out_(out) {}

    void page(xmlNode* root) {
        const double unitless = 25.4 / o_.dpi;
        bool has_w = false, has_h = false;
        double w = page_length(root, "width", unitless, has_w), h = page_length(root, "height", unitless, has_h);
        Map2 m(1.0);
        if (auto vb = attr(root, "viewBox")) {
            std::vector<double> v;
            try {
                for (glm::dvec2 p : svg::parse_points(*vb)) v.push_back(p.x), v.push_back(p.y);
            } catch (const svg::DataError& e) {
                fail(root, "viewBox: " + std::string(e.what()));
            }
            if (v.size() != 4) fail(root, "viewBox must be four numbers, got \"" + *vb + "\"");
            if (v[2] > 0 && v[3] > 0) {
                if (!has_w) w = has_h ? h * v[2] / v[3] : v[2] * unitless;
                if (!has_h) h = has_w ? w * v[3] / v[2] : v[3] * unitless;
                double sx = w / v[2], sy = h / v[3];
                glm::dvec2 align(0.5), shift(0);
                const std::string par = attr(root, "preserveAspectRatio").value_or("xMidYMid meet");
                if (par.find("none") == std::string::npos) {
                    const double s = par.find("slice") != std::string::npos ? std::max(sx, sy) : std::min(sx, sy);
                    auto pos = [&](const char* axis) {
                        const std::size_t at = par.find(axis);
                        if (at == std::string::npos) return 0.5;
                        const std::string_view k = std::string_view(par).substr(at + 1, 3);
                        return k == "Min" ? 0.0 : k == "Max" ? 1.0 : 0.5;
                    };
                    align = {pos("x"), pos("Y")};
                    sx = sy = s;
                    shift = align * (glm::dvec2(w, h) - s * glm::dvec2(v[2], v[3]));
                }
                // OpenSCAD 2021.01 moves the viewBox's y origin the wrong
                // way (measured: y + min-y, where x − min-x is right);
                // kept, so files place as they do there.
                m = translate(shift) * scale(sx, sy) * translate({-v[0], v[1]});
            }
        }
        walk(root, translate({0, h}) * scale(1, -1) * m);
    }

    void walk(xmlNode* parent, const Map2& ctm) {
        for (xmlNode* n = parent->children; n; n = n->next) {
            if (n->type != XML_ELEMENT_NODE) continue;
            if (n->ns && std::strcmp(reinterpret_cast<const char*>(n->ns->href), kSvgNs) != 0) continue;
            const std::string name = reinterpret_cast<const char*>(n->name);
            Map2 m = ctm;
            if (auto t = attr(n, "transform")) {
                try {
                    m = ctm * svg::parse_transform(*t);
                } catch (const svg::DataError& e) {
                    fail(n, "transform of <" + name + ">: " + e.what());
                }
            }
            if (name == "g" || name == "svg" || name == "a") walk(n, m);
            else if (name == "rect") rect(n, m);
            else if (name == "circle" || name == "ellipse") ellipse(n, m, name == "circle");
            else if (name == "line") open_or_closed(n, m, {{num(n, "x1"), num(n, "y1")}, {num(n, "x2"), num(n, "y2")}}, false);
            else if (name == "polyline" || name == "polygon") points(n, m, name == "polygon");
            else if (name == "path") path(n, m);
            else if (!skipped(name)) ignored(n, name);
        }
    }

    void finish() {
        for (const auto& [name, where] : ignored_)
            out_.warnings.push_back("line " + std::to_string(where.first) + ": <" + name + ">" +
                                    (where.second > 1 ? " (and " + std::to_string(where.second - 1) + " more)" : "") +
                                    " is not imported: only path, rect, circle, ellipse, line, polyline and polygon are"
                                    " drawn, as in OpenSCAD 2021.01");
    }

private:
    const SvgOptions& o_;
    SvgDrawing& out_;
    std::uint64_t points_ = 0;
    std::map<std::string, std::pair<long, int>> ignored_;  // element -> first line, count

    static bool skipped(const std::string& name) {  // not drawn by definition: no warning
        static const char* const quiet[] = {"defs",   "symbol",         "clipPath",       "mask",  "marker", "pattern",
                                            "title",  "desc",           "metadata",       "style", "script", "filter",
                                            "linearGradient", "radialGradient", "namedview"};
        for (const char* q : quiet)
            if (name == q) return true;
        return false;
    }
    void ignored(xmlNode* n, const std::string& name) {
        auto [it, fresh] = ignored_.try_emplace(name, xmlGetLineNo(n), 0);
        ++it->second.second;
    }

    [[noreturn]] static void fail(xmlNode* n, const std::string& message) {
        throw MeshFormatError("line " + std::to_string(xmlGetLineNo(n)) + ": " + message);
    }
    void warn(xmlNode* n, const std::string& message) {
        out_.warnings.push_back("line " + std::to_string(xmlGetLineNo(n)) + ": " + message);
    }

    static std::optional<std::string> attr(xmlNode* n, const char* name) {
        xmlChar* v = xmlGetNoNsProp(n, reinterpret_cast<const xmlChar*>(name));
        if (!v) return std::nullopt;
        std::string s(reinterpret_cast<const char*>(v));
        xmlFree(v);
        return s;
    }
    // A property from the attribute or, over it, the `style` declarations.
    static std::optional<std::string> property(xmlNode* n, const std::string& name) {
        std::optional<std::string> v = attr(n, name.c_str());
        if (auto style = attr(n, "style")) {
            std::size_t at = 0;
            while (at < style->size()) {
                std::size_t end = style->find(';', at);
                if (end == std::string::npos) end = style->size();
                const std::string decl = style->substr(at, end - at);
                const std::size_t colon = decl.find(':');
                auto trim = [](std::string s) {
                    const std::size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
                    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
                };
                if (colon != std::string::npos && trim(decl.substr(0, colon)) == name) v = trim(decl.substr(colon + 1));
                at = end + 1;
            }
        }
        return v;
    }

    // The number an attribute value starts with, the rest (a unit) after it.
    static double number(xmlNode* n, const char* name, const std::string& v, std::string_view& rest) {
        try {
            return svg::parse_number_prefix(v, rest);
        } catch (const svg::DataError& e) {
            fail(n, std::string(name) + " of <" + reinterpret_cast<const char*>(n->name) + ">: " + e.what());
        }
    }

    double page_length(xmlNode* n, const char* name, double unitless, bool& has) {
        auto v = attr(n, name);
        has = v.has_value();
        if (!v) return 0;
        std::string_view unit;
        const double x = number(n, name, *v, unit);
        static const std::pair<const char*, double> units[] = {{"mm", 1}, {"cm", 10}, {"in", 25.4}, {"pt", 25.4 / 72},
                                                               {"px", 25.4 / 96}};
        if (unit.empty()) return x * unitless;
        for (const auto& [u, mm] : units)
            if (unit == u) return x * mm;
        warn(n, std::string(name) + " \"" + *v + "\": the unit '" + std::string(unit) +
                    "' is not supported, read as 0 as OpenSCAD 2021.01 does");
        return 0;
    }

    // A shape's coordinate: a plain number in user units.
    double num(xmlNode* n, const char* name) {
        auto v = attr(n, name);
        if (!v) return 0;
        std::string_view rest;
        const double x = number(n, name, *v, rest);
        if (rest.empty()) return x;
        warn(n, std::string(name) + "=\"" + *v + "\": a unit on a shape's coordinate is read as 0, as OpenSCAD"
                                              " 2021.01 does");
        return 0;
    }

    void count(xmlNode* n, std::size_t k) {
        points_ += k;
        if (o_.max_items && points_ > o_.max_items)
            fail(n, "more than " + std::to_string(o_.max_items) + " points in the drawing");
    }

    void add_loops(xmlNode* n, const Map2& m, std::vector<Chain> loops) {
        std::size_t k = 0;
        for (Chain& l : loops) {
            for (glm::dvec2& p : l) {
                p = apply(m, p);
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(n, "a coordinate out of range");
            }
            k += l.size();
        }
        if (k == 0) return;
        count(n, k);
        out_.items.push_back({std::move(loops), Map2(1.0)});
    }

    void add_disc(xmlNode* n, const Map2& m) {
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(m[i][0]) || !std::isfinite(m[i][1])) fail(n, "a coordinate out of range");
        if (std::abs(glm::determinant(glm::dmat2(glm::dvec2(m[0]), glm::dvec2(m[1])))) == 0) return;
        count(n, 1);
        out_.items.push_back({{}, m});
    }

    void rect(xmlNode* n, const Map2& m) {
        const double x = num(n, "x"), y = num(n, "y"), w = num(n, "width"), h = num(n, "height");
        if (!(w > 0 && h > 0)) return;
        const bool has_rx = attr(n, "rx").has_value(), has_ry = attr(n, "ry").has_value();
        double rx = has_rx ? num(n, "rx") : 0, ry = has_ry ? num(n, "ry") : 0;
        if (!has_rx) rx = ry;
        if (!has_ry) ry = rx;
        rx = std::clamp(rx, 0.0, w / 2), ry = std::clamp(ry, 0.0, h / 2);
        auto box = [&](double x0, double y0, double x1, double y1) {
            if (x1 > x0 && y1 > y0) add_loops(n, m, {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}});
        };
        if (rx <= 0 || ry <= 0) return box(x, y, x + w, y + h);
        // Rounded: two crossed boxes and four exact corner ellipses, united.
        box(x + rx, y, x + w - rx, y + h);
        box(x, y + ry, x + w, y + h - ry);
        for (glm::dvec2 c : {glm::dvec2(x + rx, y + ry), glm::dvec2(x + w - rx, y + ry), glm::dvec2(x + rx, y + h - ry),
                             glm::dvec2(x + w - rx, y + h - ry)})
            add_disc(n, m * translate(c) * scale(rx, ry));
    }

    void ellipse(xmlNode* n, const Map2& m, bool circle) {
        const double rx = circle ? num(n, "r") : num(n, "rx"), ry = circle ? rx : num(n, "ry");
        if (rx > 0 && ry > 0) add_disc(n, m * translate({num(n, "cx"), num(n, "cy")}) * scale(rx, ry));
    }

    void points(xmlNode* n, const Map2& m, bool polygon) {
        Chain pts;
        try {
            pts = svg::parse_points(attr(n, "points").value_or(""));
        } catch (const svg::DataError& e) {
            fail(n, std::string("points of <") + (polygon ? "polygon" : "polyline") + ">: " + e.what());
        }
        open_or_closed(n, m, std::move(pts), polygon);
    }

    // A chain that ends where it starts is a closed outline, as a polygon
    // is; any other is drawn as its stroke.
    void open_or_closed(xmlNode* n, const Map2& m, Chain pts, bool closed) {
        if (pts.size() >= 3 && pts.front() == pts.back()) pts.pop_back(), closed = true;
        if (closed) {
            if (pts.size() >= 3) add_loops(n, m, {std::move(pts)});
            return;
        }
        if (pts.size() >= 2) add_loops(n, m, outline(n, {pts}));
    }

    void path(xmlNode* n, const Map2& m) {
        std::vector<svg::Subpath> subs;
        try {
            subs = svg::parse_path(attr(n, "d").value_or(""), o_.tolerance, o_.max_items);
        } catch (const svg::DataError& e) {
            fail(n, std::string("path data (d) of <path>: ") + e.what());
        }
        std::vector<Chain> closed, open;
        for (svg::Subpath& s : subs) {
            if (s.closed && s.points.size() >= 3) closed.push_back(std::move(s.points));
            else if (!s.closed && s.points.size() >= 2) open.push_back(std::move(s.points));
        }
        add_loops(n, m, std::move(closed));
        if (!open.empty()) add_loops(n, m, outline(n, open));
    }

    std::vector<Chain> outline(xmlNode* n, const std::vector<Chain>& open) {
        try {
            std::vector<Chain> out = svg::stroke_outline(open, stroke(n), o_.tolerance);
            if (out.empty() && stroke(n).width > 0)
                warn(n, std::string("the stroke of <") + reinterpret_cast<const char*>(n->name) +
                            "> is too thin for its extent to draw (below 2^-50 of it)");
            return out;
        } catch (const svg::DataError& e) {
            fail(n, std::string("the stroke of <") + reinterpret_cast<const char*>(n->name) + ">: " + e.what());
        }
    }

    // The element's own stroke properties (OpenSCAD 2021.01 inherits none
    // from groups: measured).
    svg::Stroke stroke(xmlNode* n) {
        svg::Stroke s;
        if (auto w = property(n, "stroke-width")) {
            std::string_view unit;
            s.width = number(n, "stroke-width", *w, unit);
        }
        const std::string cap = property(n, "stroke-linecap").value_or("square");
        s.cap = cap == "butt" ? svg::Stroke::Butt : cap == "round" ? svg::Stroke::Round : svg::Stroke::Square;
        const std::string join = property(n, "stroke-linejoin").value_or("miter");
        s.join = join == "round" ? svg::Stroke::RoundJoin : join == "bevel" ? svg::Stroke::Bevel : svg::Stroke::Miter;
        return s;
    }
};

// The bounding box of an item: its points, or the ellipse's extent.
void grow(const SvgItem& it, glm::dvec2& lo, glm::dvec2& hi) {
    if (it.loops.empty()) {
        const glm::dvec2 c(it.disc[2]);
        const glm::dvec2 half(std::hypot(it.disc[0][0], it.disc[1][0]), std::hypot(it.disc[0][1], it.disc[1][1]));
        lo = glm::min(lo, c - half), hi = glm::max(hi, c + half);
    }
    for (const Chain& l : it.loops)
        for (glm::dvec2 p : l) lo = glm::min(lo, p), hi = glm::max(hi, p);
}

// libxml2 reports every error; the first fatal one says what is wrong (the
// last is often only "premature end of data"). Its handler has no user
// pointer of ours, so the parse's errors go to this thread's slot.
thread_local std::string first_fatal;

void keep_first_fatal(void*, xmlErrorPtr e) {
    if (e && e->level == XML_ERR_FATAL && first_fatal.empty()) {
        std::string msg = e->message ? e->message : "unreadable";
        while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
        first_fatal = "line " + std::to_string(e->line) + ": " + msg;
    }
}

}  // namespace

SvgDrawing module_import_svg(const std::string& bytes, const SvgOptions& options) {
    std::unique_ptr<xmlParserCtxt, void (*)(xmlParserCtxtPtr)> ctxt(xmlNewParserCtxt(), xmlFreeParserCtxt);
    if (!ctxt) throw MeshFormatError("out of memory reading the XML");
    first_fatal.clear();
    ctxt->sax->serror = keep_first_fatal;
    // No network, no external entities or DTDs: only the file's own bytes.
    xmlDocPtr doc = xmlCtxtReadMemory(ctxt.get(), bytes.data(), int(bytes.size()), nullptr, nullptr,
                                      XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    std::unique_ptr<xmlDoc, void (*)(xmlDocPtr)> owned(doc, xmlFreeDoc);
    if (!doc) throw MeshFormatError("not a readable SVG file" + (first_fatal.empty() ? "" : ": " + first_fatal));
    xmlNode* root = xmlDocGetRootElement(doc);
    if (!root || std::strcmp(reinterpret_cast<const char*>(root->name), "svg") != 0)
        throw MeshFormatError(std::string("not an SVG file: the root element is <") +
                              (root ? reinterpret_cast<const char*>(root->name) : "") + ">, not <svg>");
    SvgDrawing out;
    Walker w(options, out);
    w.page(root);
    w.finish();
    if (options.center && !out.items.empty()) {
        glm::dvec2 lo(INFINITY), hi(-INFINITY);
        for (const SvgItem& it : out.items) grow(it, lo, hi);
        const glm::dvec2 shift = -(lo + hi) / 2.0;
        for (SvgItem& it : out.items) {
            it.disc = translate(shift) * it.disc;
            for (Chain& l : it.loops)
                for (glm::dvec2& p : l) p += shift;
        }
    }
    return out;
}

}  // namespace kerf::eval
