// The flattening of glyph and SVG curves (layout.hpp): how many chords keep
// a Bézier within the tolerance. Plain math, used by kerf itself (SVG paths)
// and by the font module (glyph outlines).
#include <algorithm>
#include <cmath>

#include "interpreter/text/layout.hpp"

namespace kerf::text {

namespace {

constexpr int kMaxChords = 1 << 12;  // per curve: a tolerance far below the font's own precision

int chords_for(double second_derivative, double tol) {
    if (!(second_derivative > 0)) return 1;
    const double n = std::ceil(std::sqrt(second_derivative / (8 * tol)));
    return static_cast<int>(std::clamp(n, 1.0, static_cast<double>(kMaxChords)));
}

}  // namespace

int quadratic_chords(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& p2, double tol) {
    return chords_for(2 * glm::length(p0 - 2.0 * p1 + p2), tol);  // B'' = 2 (p0 - 2 p1 + p2)
}

int cubic_chords(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& p2, const glm::dvec2& p3,
                 double tol) {
    // B''(t) = 6 ((1 - t) (p0 - 2 p1 + p2) + t (p1 - 2 p2 + p3)): its length
    // is at most the larger of the two ends'.
    return chords_for(6 * std::max(glm::length(p0 - 2.0 * p1 + p2), glm::length(p1 - 2.0 * p2 + p3)), tol);
}

}  // namespace kerf::text
