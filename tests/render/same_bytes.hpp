// Test helper: whether two renders hold the same bytes, and a render on 1
// and on 2 threads (pixels must not depend on the thread count).
#pragma once
#include <cstring>
#include <utility>

#include "render/render.hpp"

namespace kerf::test {

inline bool same_bytes(const render::Image& a, const render::Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

inline std::pair<render::Image, render::Image> on_1_and_2_threads(const csg::Scene& s, render::RenderOptions o) {
    o.threads = 1;
    render::Image one = render::render(s, o);
    o.threads = 2;
    return {std::move(one), render::render(s, o)};
}

}  // namespace kerf::test
