#include "cli/options.hpp"

#include "cli/farm_options.hpp"
#include "cli/parse_number.hpp"
#include "cli/quality_preset.hpp"
#include "cli/view/guard.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <utility>

namespace kerf::cli {

namespace {

// Options that shape an image: `kerf measure` writes none and refuses them.
bool is_image_option(const std::string& a) {
    for (const char* f : {"-o", "-W", "-H", "--spp", "--aa", "--aa-samples", "--aa-threshold", "--seed", "--preview",
                          "--max-depth", "--watch", "--crop", "--aov", "--stats", "--alpha", "--integrator", "--look",
                          "--quality", "--progressive", "--time-limit", "--no-ghosts"})
        if (a == f) return true;
    return false;
}

// --alpha needs a format with an alpha channel: PNG stores it straight,
// EXR and TIFF premultiplied (their convention). Others would drop it.
void check_alpha(Options& o) {
    if (o.render.aov != render::Aov::None) throw UsageError("--alpha applies to the shaded image, not to --aov");
    std::string ext = o.output == "-" ? ".png" : o.output.substr(std::min(o.output.size(), o.output.find_last_of('.')));
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".png") o.render.alpha = render::Alpha::Straight;
    else if (ext == ".exr" || ext == ".tif" || ext == ".tiff") o.render.alpha = render::Alpha::Premultiplied;
    else
        throw UsageError("--alpha needs an output format with an alpha channel (.png, .exr, .tif), not '" +
                         (ext.find('/') != std::string::npos || ext.empty() ? o.output : ext) + "'");
}

double parse_real(const std::string& flag, const std::string& text, double lo, double hi, const char* range) {
    double v = 0;
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || p != text.data() + text.size() || !(v >= lo && v <= hi))
        throw UsageError(flag + " expects a number " + range + ", got '" + text + "'");
    return v;
}

double parse_fraction(const std::string& flag, const std::string& text) {
    return parse_real(flag, text, 0, 1, "from 0 to 1");
}

// The value of a flag that names one of a few choices, or a usage error
// listing them ("--look expects studio or plain, got 'x'").
template <class T>
T parse_choice(const std::string& flag, const std::string& text,
               std::initializer_list<std::pair<const char*, T>> choices) {
    std::string names;
    for (std::size_t i = 0; i < choices.size(); ++i) {
        const auto& [name, value] = choices.begin()[i];
        if (text == name) return value;
        if (i > 0) names += i + 1 == choices.size() ? " or " : ", ";
        names += name;
    }
    throw UsageError(flag + " expects " + names + ", got '" + text + "'");
}

std::array<int, 4> parse_crop(const std::string& text) {
    std::array<int, 4> c{};
    std::size_t start = 0;
    for (int i = 0; i < 4; ++i) {
        std::size_t comma = text.find(',', start);
        if ((i < 3) != (comma != std::string::npos))
            throw UsageError("--crop expects x0,y0,x1,y1, got '" + text + "'");
        c[i] = parse_int<int>("--crop", text.substr(start, comma - start), 0, 1 << 20);
        start = comma + 1;
    }
    if (c[2] <= c[0] || c[3] <= c[1]) throw UsageError("--crop needs x0 < x1 and y0 < y1");
    return c;
}

void parse_define(const std::string& text, Options& o) {
    std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw UsageError("-D expects name=value, got '" + text + "'");
    o.eval.defines.emplace_back(text.substr(0, eq), text.substr(eq + 1));
}

}  // namespace

const char* usage_text() {
    return "usage:\n"
           "  kerf render SCENE.sdl [-o OUT] [-W 800] [-H 600] [--threads N]\n"
           "                        [--aa auto|off] [--aa-samples 16] [--aa-threshold 0.05] [--spp N]\n"
           "                        [--preview] [--aov depth|normal|hits] [--alpha] [--stats] [--no-progress]\n"
           "                        [-D name=value ...] [-I dir ...] [--crop x0,y0,x1,y1]\n"
           "                        [--seed N] [--precision double|float] [--base DIR]\n"
           "                        [--quality draft|good|final]  (a bundle of the sampling knobs; good is\n"
           "                                          the defaults; an explicit knob beside it wins)\n"
           "                        [--integrator whitted|path]  (path: --spp 64 by default)\n"
           "                        [--progressive] [--time-limit SECONDS]  (path: write OUT after each pass\n"
           "                                          of 1, 2, 4, ... paths per pixel; start no pass after)\n"
           "                        [--look studio|plain]  (a script without camera, lights or background)\n"
           "                        [--no-ghosts]  (no `%`/`#` ghosts over the image, as OpenSCAD's render)\n"
           "                        [--max-depth 4]  (reflections and refractions per ray, 0..32;\n"
           "                                          path: bounces per path, default 16)\n"
           "                        [--curve-tolerance 1e-4]  (text(), hull(), minkowski(), offset(): flattening, a fraction of size)\n"
           "                        [--facets auto|exact|openscad]  ($fn/$fa/$fs: docs/openscad.md \"Facets\")\n"
           "                        [--frames N [--frame I]] [--tile K/N] [--resume]\n"
           "    SCENE '-' reads standard input (includes resolve against --base DIR or the\n"
           "    working folder); -o - writes the PNG to standard output\n"
           "  kerf watch  SCENE.sdl [-o OUT] [render options]   (or: kerf render --watch ...)\n"
           "    renders, then renders again (a preview, then the full image) whenever the\n"
           "    scene or a file it includes, uses or imports is saved; Ctrl-C stops\n"
           "  kerf view   SCENE.sdl [--port N] [--host 127.0.0.1] [render options]\n"
           "    serves a live view on a loopback address (prints its URL): renders again on\n"
           "    every save; orbit, pan and zoom with the mouse; Ctrl-C stops\n"
           "  kerf check  SCENE.sdl   parse, evaluate and lower; print diagnostics only\n"
           "  kerf dump   SCENE.sdl   print the lowered, flattened CSG tree\n"
           "  kerf measure SCENE.sdl [--resolution 512] [--threads N] [--precision double|float]\n"
           "                         [--facets auto|exact|openscad]\n"
           "    volume, area, centroid and bounds of the exact solid, with error estimates\n"
           "  kerf assemble OUT TILE...   join --tile bands into the bytes of a single render\n"
           "farm (docs/farm.md): --frames N renders OUT_0001..OUT_N ($t = (I-1)/N for frame I),\n"
           "    --frame I only frame I; --tile K/N band K (0..N-1) of N as OUT_tileKofN.png;\n"
           "    --resume skips frames and bands already written by the same render\n"
           "dialect: --strict (kerf's rules, the default for .sdl) or --lenient / --openscad\n"
           "         (OpenSCAD's rules, the default for .scad; docs/openscad.md)\n"
           "warnings: --werror makes every warning an error (exit 1)\n"
           "limits (docs/spec.md §8): --max-call-depth N --max-nesting N --max-iterations N\n"
           "                  --max-list N --max-primitives N --max-steps N --max-echo-bytes N\n"
           "exit status: 0 ok, 1 scene errors, 2 bad command line or unreadable file,\n"
           "             3 render failed (e.g. output not writable)\n";
}

Options parse_options(const std::vector<std::string>& args) {
    Options o;
    if (args.empty()) throw UsageError("no command given (try 'kerf --help')");
    const std::string& cmd = args[0];
    if (cmd == "--help" || cmd == "-h" || cmd == "help") { o.command = Command::Help; return o; }
    if (cmd == "--version") { o.command = Command::Version; return o; }
    if (cmd == "assemble") return parse_assemble(args);
    if (cmd == "render") o.command = Command::Render;
    else if (cmd == "watch") o.command = Command::Watch;
    else if (cmd == "view") o.command = Command::View;
    else if (cmd == "check") o.command = Command::Check;
    else if (cmd == "dump") o.command = Command::Dump;
    else if (cmd == "measure") o.command = Command::Measure;
    else throw UsageError("unknown command '" + cmd + "' (expected render, watch, view, check, dump, measure or assemble)");

    constexpr std::uint64_t big = std::numeric_limits<std::uint32_t>::max();
    o.render.adaptive = true;  // --aa auto is the default
    std::string aa_flag, aa_knob, spp_flag;  // as given, to refuse contradictions
    int max_depth = -1;                      // --max-depth as given: the chosen integrator's
    bool aa_samples_given = false, aa_threshold_given = false;
    const QualityPreset* quality = find_quality_preset("good");  // --quality; explicit knobs override it
    std::string image_flag;  // the first option that only an image uses (refused by measure)
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (image_flag.empty() && is_image_option(a)) image_flag = a;
        auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
            return args[++i];
        };
        if (a == "-o") {
            o.output = value();
            if (o.output.empty()) throw UsageError("-o needs a file name, got ''");
        }
        else if (a == "-W") o.render.width = parse_int<int>(a, value(), 1, 32768);
        else if (a == "-H") o.render.height = parse_int<int>(a, value(), 1, 32768);
        else if (a == "--spp") {
            o.render.spp = parse_int<int>(a, value(), 1, 65536);
            spp_flag = a;
        } else if (a == "--aa") {
            const std::string& v = value();
            if (v != "auto" && v != "off") throw UsageError("--aa expects auto or off, got '" + v + "'");
            aa_flag = a + " " + v;
        } else if (a == "--aa-samples") {
            o.render.aa_samples = parse_int<int>(a, value(), 2, 4096);
            aa_knob = a;
            aa_samples_given = true;
        } else if (a == "--aa-threshold") {
            o.render.aa_threshold = parse_fraction(a, value());
            aa_knob = a;
            aa_threshold_given = true;
        } else if (a == "--quality") {
            const std::string& v = value();
            quality = find_quality_preset(v);
            if (!quality) throw UsageError("--quality expects draft, good or final, got '" + v + "'");
        }
        else if (a == "--resolution" && o.command == Command::Measure) {
            o.measure.resolution = parse_int<int>(a, value(), 8, 16384);
            if (o.measure.resolution % 2 != 0) throw UsageError("--resolution must be even, got " + args[i]);
        }
        else if (a == "--port" && o.command == Command::View) o.port = parse_int<int>(a, value(), 0, 65535);
        else if (a == "--host" && o.command == Command::View) {
            o.host = value();
            if (o.host == "localhost") o.host = "127.0.0.1";
            if (!view::is_loopback_address(o.host))
                throw UsageError("--host must be a loopback address (127.0.0.1, another 127.x.y.z or ::1): kerf view "
                                 "serves this machine only, got '" + o.host + "'");
        }
        else if (a == "--threads") o.render.threads = parse_int<int>(a, value(), 0, 1024);
        else if (a == "--max-depth") max_depth = parse_int<int>(a, value(), 0, 32);
        else if (a == "--integrator")
            o.render.integrator = parse_choice(a, value(), {std::pair{"whitted", render::Integrator::Whitted},
                                                            std::pair{"path", render::Integrator::Path}});
        else if (a == "--seed") o.render.seed = parse_int<std::uint64_t>(a, value(), 0, UINT64_MAX);
        else if (a == "--preview") o.render.preview = true;
        else if (a == "--progressive") o.progressive = true;
        else if (a == "--time-limit") o.render.time_limit = parse_real(a, value(), 1e-9, 1e7, "of seconds from 1e-9 to 1e7");
        else if (a == "--no-ghosts") o.ghosts = false;
        else if (a == "--watch" && (o.command == Command::Render || o.command == Command::Watch)) o.command = Command::Watch;
        // The dialect (docs/openscad.md): by default `.scad` files follow
        // OpenSCAD's lenient rules and everything else kerf's strict ones.
        else if (a == "--openscad" || a == "--lenient") o.eval.dialect = Dialect::Lenient;
        else if (a == "--strict") o.eval.dialect = Dialect::Strict;
        else if (a == "--werror") o.eval.werror = true;
        else if (a == "--stats") o.stats = true;
        else if (a == "--alpha") o.render.alpha = render::Alpha::Straight;  // the format settles which (below)
        else if (a == "--no-progress") o.progress = false;
        else if (a == "--crop") o.render.crop = parse_crop(value());
        else if (a == "--aov")
            o.render.aov = parse_choice(a, value(), {std::pair{"depth", render::Aov::Depth},
                                                     std::pair{"normal", render::Aov::Normal},
                                                     std::pair{"hits", render::Aov::Hits}});
        else if (a == "--look")
            o.look = parse_choice(a, value(), {std::pair{"studio", Look::Studio}, std::pair{"plain", Look::Plain}});
        else if (a == "--precision")
            o.render.double_precision = parse_choice(a, value(), {std::pair{"double", true}, std::pair{"float", false}});
        else if (a == "-D") parse_define(value(), o);
        else if (a.size() > 2 && a.rfind("-D", 0) == 0) parse_define(a.substr(2), o);
        else if (a == "--base") o.base = value();
        else if (a == "--facets")  // docs/spec.md §11: what $fn, $fa and $fs do to curves
            o.eval.facets = parse_choice(a, value(), {std::pair{"auto", FacetMode::Auto}, std::pair{"exact", FacetMode::Exact},
                                                      std::pair{"openscad", FacetMode::OpenScad}});
        else if (a == "--curve-tolerance")
            o.eval.curve_tolerance = parse_real(a, value(), 1e-9, 0.1, "from 1e-9 to 0.1");
        else if (a == "-I") o.eval.include_dirs.push_back(value());
        else if (a.size() > 2 && a.rfind("-I", 0) == 0) o.eval.include_dirs.push_back(a.substr(2));
        else if (a == "--max-call-depth") o.eval.limits.call_depth = parse_int<std::uint64_t>(a, value(), 1, 1'000'000);
        else if (a == "--max-nesting") o.eval.limits.nesting = parse_int<std::uint64_t>(a, value(), 1, 100'000);
        else if (a == "--max-iterations") o.eval.limits.loop_iterations = parse_int<std::uint64_t>(a, value(), 1, big * 16);
        else if (a == "--max-list") o.eval.limits.list_elements = parse_int<std::uint64_t>(a, value(), 1, big);
        else if (a == "--max-echo-bytes") o.eval.limits.echo_bytes = parse_int<std::uint64_t>(a, value(), 1, big * big);
        else if (a == "--max-primitives") o.eval.limits.primitives = parse_int<std::uint64_t>(a, value(), 1, big);
        else if (a == "--max-steps") o.eval.limits.steps = parse_int<std::uint64_t>(a, value(), 1, big * big);
        else if (a == "--help" || a == "-h") { o.command = Command::Help; return o; }
        else if (parse_farm_flag(args, i, o)) continue;
        else if (!a.empty() && a[0] == '-' && a != "-") throw UsageError("unknown option '" + a + "'");
        else if (o.scene.empty()) o.scene = a;
        else throw UsageError("more than one scene given ('" + o.scene + "' and '" + a + "')");
    }
    if (o.scene.empty()) throw UsageError(cmd + " needs a scene file");
    o.eval.threads = unsigned(o.render.threads);
    if (o.command == Command::Measure) {
        if (!image_flag.empty() || o.farm.any())
            throw UsageError("measure writes no image; " + (image_flag.empty() ? std::string("the farm options do") : image_flag) +
                             " does not apply to it");
        o.measure.threads = o.render.threads;
        o.measure.double_precision = o.render.double_precision;
        return o;
    }
    // The path tracer: uniform sampling, 64 paths per pixel unless --spp;
    // the Whitted tracer's one-ray looks (preview, AOVs) are not paths.
    if (o.render.integrator == render::Integrator::Path) {
        if (!aa_flag.empty() || !aa_knob.empty())
            throw UsageError("--integrator path samples every pixel alike (--spp N, default 64); drop " +
                             (aa_knob.empty() ? aa_flag : aa_knob));
        if (o.render.preview || o.render.aov != render::Aov::None)
            throw UsageError(std::string(o.render.preview ? "--preview" : "--aov") +
                             " traces one Whitted ray through each pixel centre; drop --integrator path");
        o.render.adaptive = false;
        o.eval.path_integrator = true;
        if (spp_flag.empty()) o.render.spp = quality->path_spp;
        o.render.max_path_depth = max_depth >= 0 ? max_depth : quality->max_path_depth;
    } else {
        o.render.max_reflect_depth = max_depth >= 0 ? max_depth : quality->max_reflect_depth;
        if (o.progressive || o.render.time_limit > 0)
            throw UsageError(std::string(o.progressive ? "--progressive" : "--time-limit") +
                             " applies to --integrator path, whose paths come in passes");
    }
    if (o.progressive && o.output == "-")
        throw UsageError("--progressive writes the image again after every pass; -o - (standard output) is not for it");
    if ((o.progressive || o.render.time_limit > 0) && o.farm.any())
        throw UsageError(std::string(o.progressive ? "--progressive" : "--time-limit") +
                         " does not apply to the farm: its frames and bands must not depend on a machine's speed");
    if (o.progressive && o.command == Command::View)
        throw UsageError("view always shows the path integrator's passes as they finish; drop --progressive");
    // The preset's anti-aliasing knobs fill only what was not given; under
    // --spp or --aa off they go unused, which is the preset's business, not
    // a contradiction on the command line.
    if (!aa_samples_given) o.render.aa_samples = quality->aa_samples;
    if (!aa_threshold_given) o.render.aa_threshold = quality->aa_threshold;
    // Sampling: adaptive unless --spp, --aa off, --preview or an AOV; a knob
    // that would then be ignored is an error, never silence.
    if (aa_flag == "--aa auto" && !spp_flag.empty())
        throw UsageError("--spp gives uniform sampling; it cannot be combined with --aa auto");
    if (aa_flag == "--aa off" || !spp_flag.empty()) o.render.adaptive = false;
    if (!aa_knob.empty() && !o.render.adaptive)
        throw UsageError(aa_knob + " applies to adaptive anti-aliasing, which " +
                         (spp_flag.empty() ? std::string("--aa off") : std::string("--spp")) + " turns off");
    const char* centre_only = o.render.preview ? "--preview" : o.render.aov != render::Aov::None ? "--aov" : nullptr;
    if (centre_only && (!aa_knob.empty() || aa_flag == "--aa auto" || !spp_flag.empty()))
        throw UsageError(std::string(centre_only) + " traces one ray through each pixel centre; drop " +
                         (!aa_knob.empty() ? aa_knob : !spp_flag.empty() ? spp_flag : aa_flag));
    if (centre_only) o.render.adaptive = false;
    if (o.render.crop && ((*o.render.crop)[2] > o.render.width || (*o.render.crop)[3] > o.render.height))
        throw UsageError("--crop rectangle lies outside the " + std::to_string(o.render.width) + "x" +
                         std::to_string(o.render.height) + " image");
    if (!o.base.empty() && o.scene != "-")
        throw UsageError("--base applies to a scene read from standard input ('-'), not to " + o.scene);
    if (o.command == Command::Watch && o.scene == "-")
        throw UsageError("watch needs a scene file to watch, not standard input");
    if (o.command == Command::View) {
        if (o.scene == "-") throw UsageError("view needs a scene file to watch, not standard input");
        for (const char* f : {"-o", "--crop", "--stats"})
            if (std::find(args.begin(), args.end(), f) != args.end())
                throw UsageError(std::string(f) + " does not apply to view: it writes no file, the page shows the render and its statistics");
        if (o.farm.any()) throw UsageError("view renders one image; the farm options do not apply to it");
        if (o.render.aov != render::Aov::None) throw UsageError("view shows the shaded image; --aov does not apply to it");
    }
    if (o.command == Command::Watch && o.output == "-")
        throw UsageError("watch writes a file again on each change; -o - (standard output) is not for it");
    if (o.output.empty() && o.scene == "-" && o.command == Command::Render)
        throw UsageError("a scene from standard input needs -o OUT (-o - writes the PNG to standard output)");
    if (o.output.empty()) {
        std::string base = o.scene;
        std::size_t slash = base.find_last_of('/');
        std::size_t dot = base.find_last_of('.');
        if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) base.resize(dot);
        o.output = base + ".png";
    }
    if (o.render.alpha != render::Alpha::None) check_alpha(o);
    check_farm_options(o);
    return o;
}

}  // namespace kerf::cli
