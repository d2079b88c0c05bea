// text(): a string shaped with HarfBuzz in a FreeType font, laid out the
// way OpenSCAD 2021.01 lays it out, each glyph's outline flattened within a
// known tolerance (docs/language.md, "Text"; docs/accuracy.md, "Text").
#pragma once
#include <string>
#include <vector>

#include "csg/scene.hpp"

namespace kerf::text {

struct TextParams {
    std::string text;
    double size = 10;             // the em is size · 100/72, as in OpenSCAD
    std::string font;             // empty: kDefaultFont
    std::string halign = "left";  // left | center | right
    std::string valign = "baseline";  // baseline | top | center | bottom
    double spacing = 1;           // multiplies every advance
    std::string direction;        // ltr | rtl | ttb | btt; empty: the script's own
    std::string language = "en";
    std::string script;           // ISO 15924 ("latin"); empty: detected
    // The largest distance between a flattened curve and the true outline,
    // as a fraction of `size`.
    double tolerance = 1e-4;
    bool fallback_font = false;   // the OpenSCAD dialect: a missing font is substituted
};

struct TextShape {
    // One even-odd edge set per glyph that has an outline (a space has none),
    // in the text's plane; glyphs may overlap, so they are separate shapes
    // for the caller to unite.
    std::vector<csg::Polygon2> glyphs;
    std::vector<std::string> warnings;  // a substituted font, unknown values
};

// Throws FontError (font not found or unreadable) or std::invalid_argument
// (a parameter out of its domain); the message says which.
TextShape layout_text(const TextParams& params);

// The flattening of one curve (exposed for its tests): the number of chords
// that keeps a quadratic (p0 p1 p2) or cubic (p0..p3) Bézier within `tol`,
// from the bound |B''| h²/8 on a chord's distance from its arc.
int quadratic_chords(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& p2, double tol);
int cubic_chords(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& p2, const glm::dvec2& p3,
                 double tol);

}  // namespace kerf::text
