#include "cli/assemble.hpp"

#include <charconv>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "cli/farm_key.hpp"
#include "render/image/image.hpp"
#include "render/image/png_join.hpp"

namespace kerf::cli {

namespace {

struct Band {
    std::string path;
    render::PngBand picture;
    std::map<std::string, std::string> key;
    int k = 0, n = 0;
};

int whole(const std::string& s) {
    int v = -1;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size() ? v : -1;
}

Band read_band(const std::string& path) {
    Band b;
    b.path = path;
    if (const std::string why = render::read_png_band(path, b.picture); !why.empty())
        throw TileError(path + ": " + why);
    for (const auto& [keyword, value] : b.picture.text)
        if (keyword == kFarmKeyword) b.key = parse_key(value);
    const std::string band = b.key.count("band") ? b.key["band"] : "";
    const std::size_t slash = band.find('/');
    if (slash != std::string::npos) b.k = whole(band.substr(0, slash)), b.n = whole(band.substr(slash + 1));
    // The bounds of -W, -H and --tile: a forged chunk cannot ask for more.
    constexpr int kMaxSide = 32768;
    const int width = whole(b.key["width"]), height = whole(b.key["height"]);
    if (slash == std::string::npos || b.k < 0 || b.n < 1 || b.k >= b.n || width < 1 || width > kMaxSide ||
        height < b.n || height > kMaxSide)
        throw TileError(path + ": not a band of a kerf render (render bands with kerf render --tile K/N)");
    if (b.picture.first_row < 0)
        throw TileError(path + ": has no table of its image data pieces (render it again with this kerf)");
    return b;
}

// Why `b` cannot join `first`'s render, or empty.
std::string mismatch(const Band& first, const Band& b) {
    auto differs = [&](const char* field) { return first.key.at(field) != b.key.at(field); };
    auto both = [&](const char* field) { return b.key.at(field) + ", not " + first.key.at(field); };
    if (differs("scene")) return "another scene (hash " + both("scene") + ")";
    if (differs("width") || differs("height"))
        return "another size (" + b.key.at("width") + "x" + b.key.at("height") + ", not " + first.key.at("width") +
               "x" + first.key.at("height") + ")";
    if (differs("seed")) return "another seed (" + both("seed") + ")";
    if (differs("options")) return "other options (" + both("options") + ")";
    if (b.n != first.n) return "a split into " + std::to_string(b.n) + " bands, not " + std::to_string(first.n);
    return {};
}

}  // namespace

int assemble(const Options& o) {
    // The bands are read in parallel, and their errors reported in the order
    // given.
    std::vector<Band> bands(o.tiles.size());
    std::vector<std::string> errors(o.tiles.size());
    tbb::parallel_for(std::size_t(0), o.tiles.size(), [&](std::size_t i) {
        try {
            bands[i] = read_band(o.tiles[i]);
        } catch (const std::exception& e) {
            errors[i] = e.what();
        }
    });
    for (std::size_t i = 0; i < bands.size(); ++i) {
        const std::string& path = o.tiles[i];
        if (!errors[i].empty()) throw TileError(errors[i]);
        for (const char* field : {"scene", "width", "height", "seed", "options"})
            if (!bands[i].key.count(field)) throw TileError(path + ": its kerf metadata has no " + field);
        if (const std::string why = mismatch(bands.front(), bands[i]); !why.empty())
            throw TileError(path + " is not a band of the render " + bands.front().path + " belongs to: " + why);
    }
    const Band& first = bands.front();
    const int width = whole(first.key.at("width")), height = whole(first.key.at("height")), n = first.n;
    std::vector<const Band*> by_index(std::size_t(n), nullptr);
    for (const Band& b : bands) {
        if (const Band* other = by_index[std::size_t(b.k)])
            throw TileError(other->path + " and " + b.path + " are both band " + std::to_string(b.k) + " of " +
                            std::to_string(n));
        by_index[std::size_t(b.k)] = &b;
        const auto rows = band_rows(height, b.k, n);
        if (b.picture.width != width || b.picture.height != rows[1] - rows[0] || b.picture.first_row != rows[0] ||
            b.picture.channels != first.picture.channels || b.picture.srgb != first.picture.srgb)
            throw TileError(b.path + ": its pixels are not band " + std::to_string(b.k) + " of " + std::to_string(n) +
                            " of a " + std::to_string(width) + "x" + std::to_string(height) + " render");
    }
    std::string missing;
    int count = 0;
    for (int k = 0; k < n; ++k)
        if (!by_index[std::size_t(k)]) missing += (count++ ? ", " : "") + std::to_string(k);
    if (count > 0)
        throw TileError(std::string(count == 1 ? "band " : "bands ") + missing + " of " + std::to_string(n) +
                        (count == 1 ? " is" : " are") + " missing");
    if (!render::is_8bit_output(o.output))
        throw TileError("bands hold 8-bit sRGB; " + o.output + " would store floats (assemble into PNG, JPEG, ...)");
    try {
        render::check_output_path(o.output, width, height, o.tiles);
        if (render::is_png_output(o.output)) {
            // PNG: the bands' deflated pieces joined, the very bytes a single
            // render's encoder writes (render/image/png_join.hpp).
            std::vector<const render::PngBand*> pictures;
            for (const Band* b : by_index) pictures.push_back(&b->picture);
            std::vector<unsigned char> file;
            const render::PngBand* culprit = nullptr;
            if (const std::string why = render::join_png_bands(file, pictures, &culprit); !why.empty()) {
                for (const Band* b : by_index)
                    if (&b->picture == culprit) throw TileError(b->path + ": " + why);
                throw render::ImageWriteError("cannot write " + o.output + ": " + why);
            }
            render::write_encoded(file, o.output);
            return 0;
        }
        render::Image image;
        image.width = width, image.height = height, image.channels = first.picture.channels;
        image.content = render::ImageContent::Color;
        image.srgb8.resize(std::size_t(width) * height * std::size_t(image.channels));
        const std::size_t stride = std::size_t(width) * std::size_t(image.channels);
        for (const Band* b : by_index)
            if (const std::string why = render::decode_band(b->picture, image.srgb8.data() + stride * b->picture.first_row);
                !why.empty())
                throw TileError(b->path + ": " + why);
        render::write_image(image, o.output);  // the very call a single render ends with
    } catch (const render::ImageWriteError& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return 3;
    }
    return 0;
}

}  // namespace kerf::cli
