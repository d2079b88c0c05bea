#include "cli/farm.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "cli/farm_key.hpp"
#include "cli/pipeline.hpp"
#include "cli/progress.hpp"
#include "cli/report.hpp"
#include "render/image/image.hpp"
#include "render/image/png_pieces.hpp"
#include "render/image/png_read.hpp"

namespace kerf::cli {

namespace {

namespace fs = std::filesystem;

std::string with_suffix(const std::string& output, const std::string& suffix) {
    const fs::path p(output);
    return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

std::string padded(int v, int digits) {
    std::string s = std::to_string(v);
    return std::string(s.size() < std::size_t(digits) ? std::size_t(digits) - s.size() : 0, '0') + s;
}

// --resume: whether `path` already holds this render's output, read back
// whole (every CRC) with the same metadata and size, and for a band
// (`band_row` >= 0) the table of pieces `kerf assemble` joins by. Says why
// not when a file is there but is not it.
bool finished(const std::string& path, const std::string& text, int width, int height, int band_row) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return false;
    render::PngPicture picture;
    std::string why = render::read_png(path, picture);
    if (why.empty()) {
        bool same = false, table = false;
        for (const auto& [key, value] : picture.text) {
            same = same || (key == kFarmKeyword && value == text);
            int row = -1;
            std::vector<render::PieceData> pieces;
            table = table || (key == render::kPiecesKeyword && render::parse_pieces_table(value, row, pieces) &&
                              row == band_row);
        }
        if (!same) why = "written by another render (scene, size, seed or options differ)";
        else if (picture.width != width || picture.height != height) why = "not the size of this render";
        else if (band_row >= 0 && !table) why = "has no table of its image data pieces";
    }
    if (!why.empty()) {
        std::cerr << "kerf: " << path << ": " << why << "; rendering it again\n";
        return false;
    }
    std::cerr << "kerf: " << path << ": already rendered, skipped\n";
    return true;
}

// Renders one frame or band to `path` unless --resume finds it finished;
// `band_row`: a band's first row (write_image()), -1 for a frame.
void render_one(const Options& o, const csg::Scene& scene, render::RenderOptions ro, const std::string& path,
                const std::string& text, int band_row = -1) {
    const auto [w, h] = output_size(ro);
    if (o.farm.resume && finished(path, text, w, h, band_row)) return;
    ro.srgb8 = render::is_8bit_output(path);
    render::RenderStats stats;
    render::Image image;
    {
        ProgressBar bar(o.progress);
        image = render_and_write(scene, ro, path, bar, &stats, {{kFarmKeyword, text}}, band_row);
    }
    if (o.stats) print_stats(stats, image);
}

int render_frames(const Options& o) {
    const FarmOptions& f = o.farm;
    const int first = f.frame > 0 ? f.frame : 1, last = f.frame > 0 ? f.frame : f.frames;
    const auto [w, h] = output_size(o.render);
    for (int i = first; i <= last; ++i) render::check_output_path(frame_path(o.output, i, f.frames), w, h, {o.scene});
    const auto piped = o.scene == "-" ? stdin_source(o.base) : nullptr;
    for (int i = first; i <= last; ++i) {
        // $t = (I-1)/N as the expression itself: the evaluator divides, as
        // OpenSCAD does for its animation steps.
        EvalOptions eval = o.eval;
        eval.defines.emplace_back("$t", std::to_string(i - 1) + "/" + std::to_string(f.frames));
        csg::Scene scene;
        {
            ProgressBar bar(o.progress);  // one bar at a time: gone before the render's
            scene = evaluate_and_lower(o, eval, bar, piped);
        }
        const std::string n = std::to_string(i) + "/" + std::to_string(f.frames);
        render_one(o, scene, o.render, frame_path(o.output, i, f.frames),
                   render_key(scene, o.render, o.eval.facets) + " frame=" + n);
    }
    return 0;
}

int render_band(const Options& o) {
    const FarmOptions& f = o.farm;
    const auto rows = band_rows(o.render.height, f.tile, f.tiles);
    const std::string path = tile_path(o.output, f.tile, f.tiles);
    render::check_output_path(path, o.render.width, rows[1] - rows[0], {o.scene});
    csg::Scene scene;
    {
        ProgressBar bar(o.progress);
        scene = evaluate_and_lower(o, o.eval, bar);
    }
    render::RenderOptions ro = o.render;
    ro.crop = std::array<int, 4>{0, rows[0], ro.width, rows[1]};
    const std::string n = std::to_string(f.tile) + "/" + std::to_string(f.tiles);
    // The key names the whole image; the band says which part this is.
    render_one(o, scene, ro, path, render_key(scene, o.render, o.eval.facets) + " band=" + n, rows[0]);
    return 0;
}

}  // namespace

std::string frame_path(const std::string& output, int frame, int frames) {
    return with_suffix(output, "_" + padded(frame, std::max<int>(4, int(std::to_string(frames).size()))));
}

std::string tile_path(const std::string& output, int tile, int tiles) {
    return with_suffix(output, "_tile" + padded(tile, int(std::to_string(tiles - 1).size())) + "of" +
                                   std::to_string(tiles));
}

int render_farm(const Options& o) {
    try {
        return o.farm.tiles > 0 ? render_band(o) : render_frames(o);
    } catch (const render::ImageWriteError& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return 3;
    }
}

}  // namespace kerf::cli
