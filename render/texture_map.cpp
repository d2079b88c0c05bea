#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/texture.hpp"

namespace kerf::render {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

double longitude(const glm::dvec3& q) {
    const double u = std::atan2(q.y, q.x) / kTwoPi;  // (−½, ½]
    return u < 0 ? u + 1 : u;
}

int wrap(long i, int n) {
    const long r = i % n;
    return int(r < 0 ? r + n : r);
}

}  // namespace

glm::dvec2 texture_uv(csg::TextureMapping mapping, const glm::dvec3& q) {
    switch (mapping) {
        case csg::TextureMapping::Planar: return {q.x, q.y};
        case csg::TextureMapping::Spherical: {
            const double r = glm::length(q);
            if (!(r > 0)) return {0, 0.5};
            return {longitude(q), 0.5 + std::asin(std::clamp(q.z / r, -1.0, 1.0)) / std::numbers::pi};
        }
        case csg::TextureMapping::Cylindrical: return {longitude(q), q.z};
    }
    return {0, 0};
}

glm::dvec3 texture_color(const csg::Texture& t, csg::TextureMapping mapping, bool bilinear, const glm::dvec2& uv) {
    const bool clamp_rows = mapping == csg::TextureMapping::Spherical;
    // Continuous pixel coordinates: x across from the left edge, y down from the top edge.
    const double x = uv.x * t.width, y = (1 - uv.y) * t.height;
    if (!std::isfinite(x) || !std::isfinite(y)) return glm::dvec3(0);
    auto row = [&](long j) { return clamp_rows ? int(std::clamp<long>(j, 0, t.height - 1)) : wrap(j, t.height); };
    auto pixel = [&](long i, long j) {
        const float* p = &t.rgb[(std::size_t(row(j)) * t.width + wrap(i, t.width)) * 3];
        return glm::dvec3(p[0], p[1], p[2]);
    };
    // Far out (|x| ≥ 2⁶²) a double no longer resolves pixels; the cast stays defined.
    auto cell = [](double c) { return long(std::clamp(std::floor(c), -4.0e18, 4.0e18)); };
    if (!bilinear) return pixel(cell(x), cell(y));
    const double fx = x - 0.5, fy = y - 0.5;
    const long i = cell(fx), j = cell(fy);
    const double s = fx - std::floor(fx), r = fy - std::floor(fy);
    const glm::dvec3 top = pixel(i, j) + s * (pixel(i + 1, j) - pixel(i, j));
    const glm::dvec3 bottom = pixel(i, j + 1) + s * (pixel(i + 1, j + 1) - pixel(i, j + 1));
    return top + r * (bottom - top);
}

}  // namespace kerf::render
