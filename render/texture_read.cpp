#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <filesystem>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "csg/srgb.hpp"
#include "render/image/image.hpp"
#include "render/image/image_modules.hpp"
#include "render/image/png_read.hpp"
#include "render/image/replace_file.hpp"
#include "render/texture.hpp"

namespace kerf::render {

namespace {

void take(void* context, const float* rgb, int width, int height) {
    csg::Texture& t = *static_cast<csg::Texture*>(context);
    t.width = width;
    t.height = height;
    t.rgb.assign(rgb, rgb + std::size_t(width) * height * 3);
}

// FNV-1a over the pixel floats and the size.
std::uint64_t digest(const csg::Texture& t) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    auto mix = [&](const void* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<const unsigned char*>(p)[i]) * 0x100000001b3ull;
    };
    mix(&t.width, sizeof t.width);
    mix(&t.height, sizeof t.height);
    mix(t.rgb.data(), t.rgb.size() * sizeof(float));
    return h;
}

using Key = std::tuple<std::string, long long, long long, long long>;  // path, size, mtime s, mtime ns

}  // namespace

std::shared_ptr<const csg::Texture> read_texture(const std::string& path, std::string& why) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        why = "cannot read texture \"" + path + "\": " + errno_text(errno);
        return nullptr;
    }
    if (!S_ISREG(st.st_mode)) {
        why = "texture \"" + path + "\" is not a file";
        return nullptr;
    }
    const Key key{path, st.st_size, st.st_mtim.tv_sec, st.st_mtim.tv_nsec};
    static std::mutex mutex;
    static std::map<Key, std::shared_ptr<const csg::Texture>> cache;
    std::lock_guard lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    auto t = std::make_shared<csg::Texture>();
    t->path = path;
    // 8-bit PNG (grey, RGB, RGBA: what most textures are) by kerf's own
    // checked reader; EXR, TIFF and JPEG through their own libraries; the
    // rest, and PNGs that reader refuses (palettes, 16 bits, interlacing),
    // through OpenImageIO (image_modules.hpp), whose loading costs ~0.6 s.
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    int encoded = 1;
    if (PngPicture png; ext == ".png" && read_png(path, png).empty()) {
        std::vector<float> rgb(std::size_t(png.width) * png.height * 3);
        for (std::size_t i = 0; i < rgb.size() / 3; ++i)
            for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = png.pixels[i * png.channels + (png.channels >= 3 ? c : 0)] * (1.0f / 255.0f);  // as OpenImageIO converts: the same floats
        take(t.get(), rgb.data(), png.width, png.height);
    } else {
        const ImageModule* module = nullptr;
        try {
            module = &image_module(ext);
        } catch (const ImageWriteError& e) {
            why = e.what();
            return nullptr;
        }
        char error[512] = "";
        if (!module->read(path.c_str(), take, t.get(), &encoded, error, sizeof error)) {
            why = "cannot read texture \"" + path + "\": " + error;
            return nullptr;
        }
    }
    if (encoded)
        for (float& c : t->rgb) c = float(csg::srgb_to_linear(c));
    t->digest = digest(*t);
    cache.emplace(key, t);
    return t;
}

}  // namespace kerf::render
