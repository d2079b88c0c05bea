#include "interpreter/modules/cap_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf::eval {

namespace {

struct Corner {
    std::uint32_t id;
    glm::dvec2 p;
};

// Twice the signed area of (a, b, c): positive when it turns left.
double turn(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// In the counter-clockwise triangle (a, b, c) or on its edges.
bool in_triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 p) {
    return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

// The bridge from m leaves corner i of `poly` into the region: m lies
// within the interior angle at i (the region is left of each edge).
bool opens_towards(const std::vector<Corner>& poly, std::size_t i, glm::dvec2 m) {
    const std::size_t n = poly.size();
    const glm::dvec2 a = poly[(i + n - 1) % n].p, r = poly[i].p, b = poly[(i + 1) % n].p;
    const bool left_in = turn(a, r, m) > 0, right_in = turn(r, b, m) > 0;
    return turn(a, r, b) >= 0 ? left_in && right_in : left_in || right_in;
}

// Joins `hole` (clockwise) into the boundary `poly` (counter-clockwise) by
// a bridge from the hole's rightmost corner m to a corner of `poly` it can
// see (the classic construction: the nearest boundary edge the ray from m
// along +x crosses, its right end unless another corner inside the
// triangle it spans with m blocks the view; then the blocking corner of
// the smallest angle to the ray). The bridge is walked both ways.
void join_hole(std::vector<Corner>& poly, const std::vector<Corner>& hole) {
    std::size_t im = 0;
    for (std::size_t i = 1; i < hole.size(); ++i)
        if (hole[i].p.x > hole[im].p.x) im = i;
    const glm::dvec2 m = hole[im].p;
    const std::size_t n = poly.size();
    double best = std::numeric_limits<double>::infinity();
    std::size_t target = n;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = poly[i].p, b = poly[(i + 1) % n].p;
        // An upward edge: the region lies to its left, so m sees it from inside.
        if (!(a.y < b.y) || m.y < a.y || m.y > b.y) continue;
        const double x = m.y == a.y ? a.x : m.y == b.y ? b.x : a.x + (m.y - a.y) * (b.x - a.x) / (b.y - a.y);
        if (x < m.x || x >= best) continue;
        best = x;
        target = m.y == a.y ? i : m.y == b.y || b.x > a.x ? (i + 1) % n : i;
    }
    if (target == n) {  // no edge to the right (degenerate input): any corner the bridge may leave from
        target = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (opens_towards(poly, i, m)) target = i;
    } else if (poly[target].p != glm::dvec2(best, m.y)) {
        // Corners inside the triangle (m, crossing, target) may hide the target.
        const glm::dvec2 hit(best, m.y), t = poly[target].p;
        const bool up = t.y > m.y;
        double best_tan = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i) {
            const glm::dvec2 r = poly[i].p;
            if (i == target || r.x < m.x) continue;
            const bool inside = up ? in_triangle(m, hit, t, r) : in_triangle(m, t, hit, r);
            if (!inside || !opens_towards(poly, i, m)) continue;
            const double tan = std::abs(r.y - m.y) / (r.x - m.x);
            if (tan < best_tan || (tan == best_tan && r.x < poly[target].p.x)) best_tan = tan, target = i;
        }
    }
    std::vector<Corner> out;
    out.reserve(n + hole.size() + 2);
    out.insert(out.end(), poly.begin(), poly.begin() + std::ptrdiff_t(target) + 1);
    if (poly[target].p == m) {
        // The hole touches the boundary there: walked in without a bridge,
        // its corner and the boundary's one point (welded by the caller).
        for (std::size_t k = 1; k <= hole.size(); ++k) out.push_back(hole[(im + k) % hole.size()]);
        out.insert(out.end(), poly.begin() + std::ptrdiff_t(target) + 1, poly.end());
        poly = std::move(out);
        return;
    }
    for (std::size_t k = 0; k <= hole.size(); ++k) out.push_back(hole[(im + k) % hole.size()]);
    out.insert(out.end(), poly.begin() + std::ptrdiff_t(target), poly.end());
    poly = std::move(out);
}

// Cuts the simple (possibly bridged) counter-clockwise boundary into ears.
void clip_ears(const std::vector<Corner>& poly, std::vector<std::array<std::uint32_t, 3>>& out) {
    const std::size_t n = poly.size();
    std::vector<std::size_t> prev(n), next(n);
    for (std::size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
    auto corner_turn = [&](std::size_t i) { return turn(poly[prev[i]].p, poly[i].p, poly[next[i]].p); };
    auto is_ear = [&](std::size_t i) {
        if (corner_turn(i) <= 0) return false;
        const glm::dvec2 a = poly[prev[i]].p, b = poly[i].p, c = poly[next[i]].p;
        // Only a corner that turns right (or not at all) can lie inside an ear.
        for (std::size_t j = next[next[i]]; j != prev[i]; j = next[j]) {
            const glm::dvec2 q = poly[j].p;
            if (q == a || q == b || q == c || corner_turn(j) > 0) continue;
            if (in_triangle(a, b, c, q)) return false;
        }
        return true;
    };
    std::size_t left = n, i = 0, tried = 0;
    while (left > 3) {
        if (tried == left) {
            // No ear (rounding in a degenerate boundary): the corner turning
            // most to the left, an ear of little or no area.
            std::size_t pick = i;
            for (std::size_t j = next[i]; j != i; j = next[j])
                if (corner_turn(j) > corner_turn(pick)) pick = j;
            i = pick;
        } else if (!is_ear(i)) {
            i = next[i], ++tried;
            continue;
        }
        out.push_back({poly[prev[i]].id, poly[i].id, poly[next[i]].id});
        next[prev[i]] = next[i], prev[next[i]] = prev[i];
        i = prev[i], --left, tried = 0;
    }
    out.push_back({poly[prev[i]].id, poly[i].id, poly[next[i]].id});
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> cap_triangles(std::span<const std::vector<glm::dvec2>> rings) {
    std::vector<std::array<std::uint32_t, 3>> out;
    std::vector<std::vector<Corner>> corners(rings.size());
    std::uint32_t id = 0;
    for (std::size_t r = 0; r < rings.size(); ++r)
        for (glm::dvec2 p : rings[r]) corners[r].push_back({id++, p});
    if (rings.empty() || corners[0].size() < 3) return out;
    // Holes by their rightmost corner, farthest first: each bridge then
    // stays clear of the holes still to come.
    std::vector<std::size_t> holes;
    for (std::size_t r = 1; r < rings.size(); ++r)
        if (corners[r].size() >= 3) holes.push_back(r);
    auto right = [&](std::size_t r) {
        double x = -std::numeric_limits<double>::infinity();
        for (const Corner& c : corners[r]) x = std::max(x, c.p.x);
        return x;
    };
    std::stable_sort(holes.begin(), holes.end(), [&](std::size_t a, std::size_t b) { return right(a) > right(b); });
    std::vector<Corner> poly = corners[0];
    for (std::size_t r : holes) join_hole(poly, corners[r]);
    clip_ears(poly, out);
    return out;
}

}  // namespace kerf::eval
