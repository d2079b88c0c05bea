// The image a render fills: allocated once for the region (the crop or the
// whole image), not zeroed (every value is written), and written pixel by
// pixel in full-image coordinates. Colour goes in as linear floats, or, for
// an 8-bit file, straight in as sRGB codes (RenderOptions::srgb8).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include <glm/glm.hpp>

#include "render/image/image.hpp"
#include "render/image/srgb_bytes.hpp"

namespace kerf::render {

class PixelStore {
public:
    PixelStore(Image& image, const std::array<int, 4>& region, int channels, ImageContent content, bool bytes)
        : x0_(region[0]), y0_(region[1]), bytes_(bytes), srgb_(srgb_table()) {
        image.width = region[2] - region[0];
        image.height = region[3] - region[1];
        image.channels = channels;
        image.content = content;
        const std::size_t values = std::size_t(image.width) * image.height * channels;
        if (bytes) image.srgb8.resize(values); else image.pixels.resize(values);
        // Never resized again: the pixel loop keeps the addresses and sizes in
        // members of its own, not re-read through the Image after every byte
        // store (a byte store may alias anything, so the compiler reloads).
        srgb8_ = image.srgb8.data(), pixels_ = image.pixels.data();
        width_ = std::size_t(image.width), channels_ = std::size_t(channels);
    }

    // The colour most pixels get (the background): its codes are found
    // once, and a pixel of exactly that colour copies them.
    void expect(const glm::dvec3& c) {
        common_ = c;
        for (int i = 0; i < 3; ++i) common_bytes_[i] = srgb_byte(srgb_, float(c[i]));
    }

    [[gnu::always_inline]] void color(int x, int y, const glm::dvec3& c) {
        const std::size_t at = index(x, y);
        if (bytes_) {
            // The codes first, then three stores (not std::copy: that became
            // a memmove call per pixel).
            std::uint8_t* to = srgb8_ + at;
            const bool common = c == common_;
            const std::uint8_t r = common ? common_bytes_[0] : srgb_byte(srgb_, float(c.x));
            const std::uint8_t g = common ? common_bytes_[1] : srgb_byte(srgb_, float(c.y));
            const std::uint8_t b = common ? common_bytes_[2] : srgb_byte(srgb_, float(c.z));
            to[0] = r, to[1] = g, to[2] = b;
        } else {
            float* to = pixels_ + at;
            to[0] = float(c.x), to[1] = float(c.y), to[2] = float(c.z);
        }
    }
    // Pixels [x0, x1) of row y, each as color(x, y, c) would store it: the
    // first through color, the rest copies of its three values (a culled
    // block's row of background, without a comparison per pixel).
    void fill(int x0, int x1, int y, const glm::dvec3& c) {
        if (x1 <= x0) return;
        color(x0, y, c);
        const std::size_t at = index(x0, y), n = std::size_t(x1 - x0);
        if (bytes_) {
            std::uint8_t* to = srgb8_ + at;
            const std::uint8_t r = to[0], g = to[1], b = to[2];
            for (std::size_t i = 1; i < n; ++i) to[i * channels_] = r, to[i * channels_ + 1] = g, to[i * channels_ + 2] = b;
        } else {
            float* to = pixels_ + at;
            const float r = to[0], g = to[1], b = to[2];
            for (std::size_t i = 1; i < n; ++i) to[i * channels_] = r, to[i * channels_ + 1] = g, to[i * channels_ + 2] = b;
        }
    }
    bool bytes() const { return bytes_; }
    // An sRGB image's pixel from its codes, red in the low byte: those
    // color() would store for the colour they encode.
    void codes(int x, int y, std::uint32_t rgb) { store3(srgb8_ + index(x, y), rgb); }
    // codes() for pixels [x, x + n) of row y; `rgb[i]` for pixel x + i,
    // skipped where `skip[i]`.
    void codes_row(int x, int y, int n, const std::uint32_t* rgb, const bool* skip) {
        std::uint8_t* to = srgb8_ + index(x, y);
        for (int i = 0; i < n; ++i, to += channels_)
            if (!skip[i]) store3(to, rgb[i]);
    }
    static void store3(std::uint8_t* to, std::uint32_t rgb) {
        to[0] = std::uint8_t(rgb), to[1] = std::uint8_t(rgb >> 8), to[2] = std::uint8_t(rgb >> 16);
    }
    // Colour and coverage `a` (0..1): `c` is the pixel's mean over all its
    // samples, misses seeing `background`; the hits' own share is
    // c - (1 - a)·background (premultiplied), divided by a when straight.
    void color_alpha(int x, int y, glm::dvec3 c, double a, const glm::dvec3& background, bool premultiplied) {
        c -= (1 - a) * background;
        if (a == 0) c = glm::dvec3(0.0);  // exactly: the mean of n backgrounds is not quite one
        else if (!premultiplied) c /= a;
        color(x, y, glm::max(c, glm::dvec3(0.0)));
        const std::size_t at = index(x, y) + 3;
        if (bytes_) srgb8_[at] = std::uint8_t(std::lround(std::clamp(a, 0.0, 1.0) * 255));
        else pixels_[at] = float(a);
    }
    // The float values of an AOV pixel.
    float* values(int x, int y) { return pixels_ + index(x, y); }

private:
    std::size_t index(int x, int y) const {
        return (std::size_t(y - y0_) * width_ + std::size_t(x - x0_)) * channels_;
    }
    int x0_, y0_;
    bool bytes_;
    std::uint8_t* srgb8_;
    float* pixels_;
    std::size_t width_, channels_;
    const SrgbTable& srgb_;
    glm::dvec3 common_{-1.0};  // before expect(): -1 gives code 0, as its bytes say
    std::uint8_t common_bytes_[3] = {0, 0, 0};
};

}  // namespace kerf::render
