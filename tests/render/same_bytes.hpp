// Test helper: whether two renders hold the same bytes, and a render on 1
// and on 2 threads (pixels must not depend on the thread count).
#pragma once
#include <cstddef>
#include <cstring>
#include <utility>

#include "render/render.hpp"

namespace kerf::test {

// memcmp of an empty store's null data() is undefined even for 0 bytes
// (UBSan's nonnull-attribute), and an image holds floats or 8-bit codes.
inline bool same_memory(const void* a, const void* b, std::size_t n) { return n == 0 || std::memcmp(a, b, n) == 0; }

inline bool same_bytes(const render::Image& a, const render::Image& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           a.pixels.size() == b.pixels.size() && a.srgb8.size() == b.srgb8.size() &&
           same_memory(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) &&
           same_memory(a.srgb8.data(), b.srgb8.data(), a.srgb8.size());
}

inline std::pair<render::Image, render::Image> on_1_and_2_threads(const csg::Scene& s, render::RenderOptions o) {
    o.threads = 1;
    render::Image one = render::render(s, o);
    o.threads = 2;
    return {std::move(one), render::render(s, o)};
}

}  // namespace kerf::test
