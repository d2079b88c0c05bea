#include "render/image/netpbm.hpp"

#include <bit>
#include <cstring>
#include <string>

#include "csg/srgb.hpp"
#include "render/image/srgb_bytes.hpp"

namespace kerf::render {

namespace {
double luminance(double r, double g, double b) { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
}  // namespace

Image grey_image(const Image& colour) {
    if (colour.channels == 1) return colour;
    Image grey;
    grey.width = colour.width, grey.height = colour.height, grey.channels = 1, grey.content = colour.content;
    const std::size_t n = std::size_t(colour.width) * colour.height, c = std::size_t(colour.channels);
    if (!colour.srgb8.empty()) {
        double linear[256];
        for (int i = 0; i < 256; ++i) linear[i] = csg::srgb_to_linear(i / 255.0);
        const SrgbTable& table = srgb_table();
        grey.srgb8.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint8_t* p = &colour.srgb8[i * c];
            grey.srgb8[i] = srgb_byte(table, float(luminance(linear[p[0]], linear[p[1]], linear[p[2]])));
        }
    } else {
        grey.pixels.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const float* p = &colour.pixels[i * c];
            grey.pixels[i] = float(luminance(p[0], p[1], p[2]));
        }
    }
    return grey;
}

std::vector<unsigned char> encode_pfm(const Image& image) {
    static_assert(std::endian::native == std::endian::little, "PFM is written little-endian (scale -1)");
    const std::string header = std::string(image.channels == 1 ? "Pf" : "PF") + "\n" + std::to_string(image.width) +
                               " " + std::to_string(image.height) + "\n-1.0\n";
    const std::size_t row = std::size_t(image.width) * image.channels * sizeof(float);
    std::vector<unsigned char> out(header.size() + row * image.height);
    std::memcpy(out.data(), header.data(), header.size());
    for (int y = 0; y < image.height; ++y)
        std::memcpy(out.data() + header.size() + row * std::size_t(image.height - 1 - y),
                    image.pixels.data() + std::size_t(y) * image.width * image.channels, row);
    return out;
}

}  // namespace kerf::render
