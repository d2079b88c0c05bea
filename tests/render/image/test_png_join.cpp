// PNG bands joined undecoded (png_join.hpp): the join of an image's bands,
// each encoded as a band (encode_png with its first row), must be the bytes
// encode_png gives for the whole image, and libpng must read the pixels
// back (the oracle for the stream itself: another decoder than ours).
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "render/image/png_file.hpp"
#include "render/image/png_join.hpp"
#include "render/image/png_read.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("kerf_png_join_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Noise with flat runs and smooth ramps: neither filter nor run-length
// matching hides a wrong row.
std::vector<std::uint8_t> picture(int width, int height, int channels) {
    std::vector<std::uint8_t> px(std::size_t(width) * height * channels);
    std::uint32_t state = 99;
    for (std::size_t i = 0; i < px.size(); ++i) {
        state = state * 1664525u + 1013904223u;
        const int y = int(i / (std::size_t(width) * channels));
        px[i] = y % 5 == 1 ? 40 : y % 5 == 2 ? std::uint8_t(i / channels) : std::uint8_t(state >> 24);
    }
    return px;
}

void save(const fs::path& path, const std::vector<unsigned char>& bytes) {
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// The bands [cuts[i], cuts[i+1]) of `px`, each written to a file as a band
// and read back as a PngBand.
std::vector<render::PngBand> bands_of(const fs::path& dir, const std::vector<std::uint8_t>& px, int width,
                                      int channels, const std::vector<int>& cuts) {
    std::vector<render::PngBand> bands(cuts.size() - 1);
    const std::size_t stride = std::size_t(width) * channels;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        std::vector<unsigned char> file;
        REQUIRE(render::encode_png(file, px.data() + stride * cuts[i], width, cuts[i + 1] - cuts[i], channels, true,
                                   {{"kerf", "band"}}, cuts[i])
                    .empty());
        const fs::path path = dir / ("band" + std::to_string(i) + ".png");
        save(path, file);
        REQUIRE(render::read_png_band(path.string(), bands[i]).empty());
        REQUIRE(bands[i].first_row == cuts[i]);
    }
    return bands;
}

}  // namespace

TEST_CASE("PNG bands join undecoded into the bytes of the whole image", "[png_join]") {
    const fs::path dir = fresh_dir("bytes");
    const struct {
        int width, channels;
        std::vector<int> cuts;
    } cases[] = {
        {37, 3, {0, 16, 32, 61}},            // cuts on the pieces' grid: nothing to re-encode
        {37, 3, {0, 7, 8, 9, 40, 61}},       // bands inside one piece, one row each
        {1, 1, {0, 5, 33}},                  // one pixel wide: Sub has nothing to the left
        {23, 4, {0, 17, 18, 47, 48, 49}},    // RGBA, cuts beside the grid
        {300, 3, {0, 135, 270, 405, 540}},   // a poster's 135-row bands
        {5, 3, {0, 3}},                      // one band, shorter than a piece
    };
    for (const auto& c : cases) {
        const int height = c.cuts.back();
        INFO(c.width << "x" << height << "x" << c.channels << ", " << c.cuts.size() - 1 << " bands");
        const auto px = picture(c.width, height, c.channels);
        std::vector<unsigned char> whole;
        REQUIRE(render::encode_png(whole, px.data(), c.width, height, c.channels, true).empty());
        const auto bands = bands_of(dir, px, c.width, c.channels, c.cuts);
        std::vector<const render::PngBand*> order;
        for (const auto& b : bands) order.push_back(&b);
        std::vector<unsigned char> joined;
        REQUIRE(render::join_png_bands(joined, order).empty());
        CHECK(joined == whole);
        // libpng reads the pixels back, and decode_band() agrees with it.
        save(dir / "joined.png", joined);
        render::PngPicture back;
        REQUIRE(render::read_png((dir / "joined.png").string(), back).empty());
        CHECK(back.pixels == px);
        std::vector<std::uint8_t> decoded(px.size());
        const std::size_t stride = std::size_t(c.width) * c.channels;
        for (const auto& b : bands) REQUIRE(render::decode_band(b, decoded.data() + stride * b.first_row).empty());
        CHECK(decoded == px);
    }
    fs::remove_all(dir);
}

TEST_CASE("a band whose pieces do not match its table or whose chunks are damaged is refused", "[png_join]") {
    const fs::path dir = fresh_dir("damaged");
    const int width = 20, height = 40;
    const auto px = picture(width, height, 3);
    std::vector<unsigned char> file;
    REQUIRE(render::encode_png(file, px.data(), width, height, 3, true, {}, 8).empty());
    const std::string good(file.begin(), file.end());
    const std::size_t table = good.find("kerf pieces");
    REQUIRE(table != std::string::npos);
    auto read = [&](std::string bytes) {
        save(dir / "b.png", std::vector<unsigned char>(bytes.begin(), bytes.end()));
        render::PngBand band;
        return render::read_png_band((dir / "b.png").string(), band);
    };
    CHECK(read(good).empty());
    // A flipped byte in the image data: its chunk's CRC.
    std::string bad = good;
    const std::size_t idat = good.find("IDAT");
    bad[idat + 40] = char(bad[idat + 40] ^ 1);
    CHECK(read(bad) == "IDAT: CRC error");
    CHECK(read(good.substr(0, good.size() - 20)) == "the file ends early");
    CHECK(read("\x89PNG not really") == "not a PNG file");
    // The table edited and its CRC made good again: no longer the data's.
    auto with_table = [&](const std::string& value) {
        std::vector<unsigned char> f;
        REQUIRE(render::encode_png(f, px.data(), width, height, 3, true, {{"kerf pieces", value}}).empty());
        return std::string(f.begin(), f.end());  // a plain image with a forged table
    };
    const std::size_t end = good.find('\0', table);
    const std::string value = good.substr(end + 1, good.find("IDAT") - 8 - end - 1);
    REQUIRE(value.rfind("row=8 ", 0) == 0);
    CHECK(read(with_table("row=8 1:00000001")) == "its table of image data pieces does not fit its rows");
    CHECK(read(with_table("rows=0")) == "its table of image data pieces is damaged");
    std::string pieces = value.substr(6);
    // Cut at 8 (the band's first row) as a plain image from row 0 is not:
    // the same count of pieces (3 each way), other sizes.
    CHECK(read(with_table("row=0 " + pieces)) != "");
    fs::remove_all(dir);
}
