#include "cli/farm_options.hpp"

#include <cstdint>

#include "cli/parse_number.hpp"

namespace kerf::cli {

namespace {

constexpr int kMaxFrames = 1'000'000;
constexpr int kMaxTiles = 32768;  // at most one band per row of the tallest image

bool ends_with_png(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".png";
}

}  // namespace

bool parse_farm_flag(const std::vector<std::string>& args, std::size_t& i, Options& o) {
    const std::string& a = args[i];
    if (a != "--frames" && a != "--frame" && a != "--tile" && a != "--resume") return false;
    if (a == "--resume") {
        o.farm.resume = true;
        return true;
    }
    if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
    const std::string& v = args[++i];
    if (a == "--frames") o.farm.frames = parse_int<int>(a, v, 1, kMaxFrames);
    else if (a == "--frame") o.farm.frame = parse_int<int>(a, v, 1, kMaxFrames);
    else {
        const std::size_t slash = v.find('/');
        if (slash == std::string::npos) throw UsageError("--tile expects K/N (band K of N, K from 0), got '" + v + "'");
        o.farm.tiles = parse_int<int>("--tile N", v.substr(slash + 1), 1, kMaxTiles);
        o.farm.tile = parse_int<int>("--tile K", v.substr(0, slash), 0, kMaxTiles);
        if (o.farm.tile >= o.farm.tiles)
            throw UsageError("--tile " + v + ": K counts from 0, so it must be less than N = " +
                             std::to_string(o.farm.tiles));
    }
    return true;
}

void check_farm_options(const Options& o) {
    const FarmOptions& f = o.farm;
    if (o.command == Command::Watch && (f.any() || f.resume || f.frame > 0))
        throw UsageError("watch renders one image on each change; --frames, --frame, --tile and --resume are for "
                         "kerf render");
    if (o.command != Command::Render) return;  // check and dump ignore render options (docs/spec.md §7)
    if (f.frame > 0 && f.frames == 0)
        throw UsageError("--frame I needs --frames N, the animation's length ($t = (I-1)/N)");
    if (f.frame > f.frames)
        throw UsageError("--frame " + std::to_string(f.frame) + " lies beyond --frames " + std::to_string(f.frames));
    if (f.resume && !f.any()) throw UsageError("--resume applies to --frames and --tile");
    if (!f.any()) return;
    const char* flag = f.frames > 0 ? "--frames" : "--tile";
    if (f.frames > 0 && f.tiles > 0)
        throw UsageError("--tile splits one image: tile one frame with -D '$t=...' instead of --frames");
    if (o.output == "-") throw UsageError(std::string(flag) + " writes numbered files; -o - names none");
    if (f.frames > 0)
        for (const auto& d : o.eval.defines)
            if (d.first == "$t") throw UsageError("--frames sets $t for each frame; drop -D '$t=...'");
    if (f.tiles > 0) {
        if (o.render.crop) throw UsageError("--tile renders a band of the whole image; drop --crop");
        if (o.render.aov != render::Aov::None)
            throw UsageError("--tile joins colour renders; --aov images are normalised over the whole picture");
        if (f.tiles > o.render.height)
            throw UsageError("--tile " + std::to_string(f.tile) + "/" + std::to_string(f.tiles) + ": " +
                             std::to_string(f.tiles) + " bands do not fit in " + std::to_string(o.render.height) +
                             " rows");
    }
    // The join and the resume check read the metadata kept in a PNG text chunk.
    if ((f.tiles > 0 || f.resume) && !ends_with_png(o.output))
        throw UsageError(std::string(f.tiles > 0 ? "--tile" : "--resume") + " needs PNG output (the metadata "
                         "that joins and checks the files is a PNG text chunk), got -o " + o.output);
}

Options parse_assemble(const std::vector<std::string>& args) {
    Options o;
    o.command = Command::Assemble;
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--help" || a == "-h") {
            o.command = Command::Help;
            return o;
        }
        if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option '" + a + "' for assemble");
        if (o.output.empty()) o.output = a;
        else o.tiles.push_back(a);
    }
    if (o.output.empty()) throw UsageError("assemble needs an output file and the tiles: kerf assemble OUT TILE...");
    if (o.tiles.empty()) throw UsageError("assemble needs the tiles to join after " + o.output);
    return o;
}

}  // namespace kerf::cli
