// `kerf watch` (docs/spec.md §13) as a child process on a scene in a temp
// folder: saving an included file renders again (the image equals what
// `kerf render` makes of the new files), an error keeps the last image and
// is reported at file:line:col, a burst of saves renders once or twice, the
// watched set follows the includes, and a signal leaves no temporary behind.
// Every wait is a poll with a deadline.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <set>
#include <thread>

#include "tests/cli/run_kerf.hpp"
#include "tests/cli/spawn_kerf.hpp"

namespace fs = std::filesystem;

namespace {

using namespace std::chrono_literals;

const std::string kScene = "include <part.sdl>\ncamera(position = [0, -5, 2], look_at = [0, 0, 0]);\n";

// A kerf watch the test owns: killed and reaped however the test ends.
struct Watch {
    pid_t pid = -1;
    fs::path err;
    Watch(const fs::path& dir, std::vector<std::string> args, SpawnOptions options = {}) : err(dir / "watch.err") {
        options.stderr_path = err.string();
        pid = spawn_kerf(args, options);
        REQUIRE(pid > 0);
    }
    Watch(Watch&& other) noexcept : pid(other.pid), err(other.err) { other.pid = -1; }
    Watch(const Watch&) = delete;
    Watch& operator=(const Watch&) = delete;
    ~Watch() {
        if (pid > 0) {
            ::kill(pid, SIGKILL);
            wait_kerf(pid);
        }
    }
    std::string log() const { return slurp(err); }
    int rendered() const {
        const std::string text = log();
        int n = 0;
        for (std::size_t at = 0; (at = text.find("kerf watch: rendered ", at)) != std::string::npos; ++at) ++n;
        return n;
    }
    // Ends it with `sig` and returns its exit status.
    int stop(int sig) {
        ::kill(pid, sig);
        const int status = wait_kerf(pid);
        pid = -1;
        return status;
    }
};

// Polls `done` every 10 ms for up to `limit`.
template <typename F>
bool within(std::chrono::milliseconds limit, F done) {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (!done()) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(10ms);
    }
    return true;
}

// scene.sdl including part.sdl (a sphere) in `dir`, watched into out.png
// and rendered once.
Watch watch_scene(const fs::path& dir) {
    write_file(dir / "part.sdl", "sphere(1);\n");
    write_file(dir / "scene.sdl", kScene);
    Watch w(dir, {"watch", (dir / "scene.sdl").string(), "-o", (dir / "out.png").string(), "-W", "48", "-H", "36"});
    REQUIRE(within(10s, [&] { return w.rendered() == 1; }));
    return w;
}

// As editors that save by rename do (Vim, most IDEs): a new inode.
void save_by_rename(const fs::path& path, const std::string& text) {
    write_file(path.string() + ".new", text);
    fs::rename(path.string() + ".new", path);
}

// What `kerf render` makes of the scene as it is now, at the watch's size.
std::string reference(const fs::path& dir, const fs::path& scene) {
    const auto ref = dir / "ref" / "ref.png";
    fs::create_directories(ref.parent_path());
    const KerfRun r = run_kerf("render '" + scene.string() + "' -W 48 -H 36 -o '" + ref.string() + "'", dir / "ref");
    REQUIRE(r.status == 0);
    return slurp(ref);
}

bool whole_png(const std::string& bytes) {
    static const std::string iend("IEND\xae\x42\x60\x82", 8);
    return bytes.size() > 20 && bytes.compare(1, 3, "PNG") == 0 && bytes.compare(bytes.size() - 8, 8, iend) == 0;
}

std::set<std::string> names_in(const fs::path& dir) {
    std::set<std::string> n;
    for (const auto& e : fs::directory_iterator(dir)) n.insert(e.path().filename().string());
    return n;
}

}  // namespace

TEST_CASE("kerf watch renders again when an included file is saved and keeps the last image on an error", "[watch]") {
    const auto dir = test_dir("watch_loop");
    const auto scene = dir / "scene.sdl", part = dir / "part.sdl", out = dir / "out.png";
    Watch w = watch_scene(dir);
    const std::string first = slurp(out);
    CHECK(first == reference(dir, scene));

    save_by_rename(part, "cube(1.5, center = true);\n");
    REQUIRE(within(10s, [&] { return w.rendered() == 2; }));
    const std::string second = slurp(out);
    CHECK(second != first);
    CHECK(second == reference(dir, scene));

    // A syntax error in the included file: located there, and the image stays.
    write_file(part, "cube(1.5, center = true);\nsphere(;\n");
    const std::string located = part.string() + ":2:8: error: ";
    REQUIRE(within(10s, [&] { return w.log().find("keeps the last good image") != std::string::npos; }));
    CHECK(w.log().find(located) != std::string::npos);
    CHECK(slurp(out) == second);
    CHECK(w.rendered() == 2);

    // The scene now includes another file instead: that one is watched,
    // the old one no longer.
    const auto other = dir / "other.sdl";
    write_file(other, "cylinder(h = 2, r = 0.5, center = true);\n");
    write_file(scene, "include <other.sdl>\ncamera(position = [0, -5, 2], look_at = [0, 0, 0]);\n");
    REQUIRE(within(10s, [&] { return w.rendered() == 3; }));
    write_file(other, "cylinder(h = 2, r = 1, center = true);\n");
    REQUIRE(within(10s, [&] { return w.rendered() == 4; }));
    CHECK(slurp(out) == reference(dir, scene));
    write_file(part, "sphere(0.2);\n");
    std::this_thread::sleep_for(500ms);  // debounce and render time, many times over
    CHECK(w.rendered() == 4);

    // Ctrl-C while it waits: ended by the signal, nothing left but the files.
    const auto before = names_in(dir);
    CHECK(w.stop(SIGINT) == 128 + SIGINT);
    CHECK(names_in(dir) == before);
    CHECK(whole_png(slurp(out)));
}

TEST_CASE("kerf watch renders a burst of ten saves once or twice", "[watch]") {
    const auto dir = test_dir("watch_burst");
    const auto scene = dir / "scene.sdl", part = dir / "part.sdl", out = dir / "out.png";
    Watch w = watch_scene(dir);
    for (int i = 1; i <= 10; ++i) {  // an editor's autosave, or a formatter, in quick succession
        write_file(part, "sphere(" + std::to_string(0.5 + 0.1 * i) + ");\n");
        std::this_thread::sleep_for(5ms);
    }
    REQUIRE(within(10s, [&] { return w.rendered() >= 2; }));
    std::this_thread::sleep_for(1500ms);  // past the longest debounce: any late render has shown
    const int renders = w.rendered() - 1;
    INFO(w.log());
    CHECK(renders >= 1);
    CHECK(renders <= 2);
    CHECK(slurp(out) == reference(dir, scene));  // the last save is what shows
}

TEST_CASE("kerf watch stopped by a signal while writing leaves the old image and no temporary", "[watch]") {
    const auto dir = test_dir("watch_signal");
    // Cheap pixels, a big file: a 3000x2000 BMP takes tens of milliseconds to write.
    const auto scene = dir / "far.sdl", out = dir / "out.bmp";
    write_file(scene, "translate([1000, 0, 0]) cube(0.01);\n");
    const std::string before = "an older image";
    write_file(out, before);
    const auto expected = names_in(dir);
    for (const int sig : {SIGINT}) {  // SIGTERM takes the same path (test_output_path.cpp)
        INFO("signal " << sig);
        SpawnOptions options;
        options.without_tmpfile = true;  // a named temporary, the one that could be left behind
        Watch w(dir, {"watch", scene.string(), "-o", out.string(), "-W", "3000", "-H", "2000", "--preview"}, options);
        bool caught = false;
        int status = -1;
        for (int attempt = 0; attempt < 5 && !caught && status == -1; ++attempt) {
            caught = stop_while_writing(w.pid, dir, status, 5.0);
            if (!caught) write_file(scene, "translate([1000, 0, 0]) cube(0.01);\n");  // missed it: render again
        }
        REQUIRE(caught);
        const std::string shown = slurp(out);  // what the interrupted write would have replaced
        ::kill(w.pid, sig);
        ::kill(w.pid, SIGCONT);
        CHECK(wait_kerf(w.pid) == 128 + sig);
        w.pid = -1;
        auto now = names_in(dir);
        now.erase("watch.err");
        CHECK(now == expected);
        CHECK(slurp(out) == shown);
        write_file(out, before);
    }
}

TEST_CASE("kerf render --watch is kerf watch, standard input and output and the farm flags are refused", "[watch]") {
    const auto dir = test_dir("watch_options");
    const auto scene = write_file(dir / "ball.sdl", "sphere(1);\n");
    Watch w(dir, {"render", scene, "--watch", "-W", "16", "-H", "12"});
    REQUIRE(within(10s, [&] { return w.rendered() == 1; }));
    CHECK(whole_png(slurp(dir / "ball.png")));  // SCENE.png beside the scene, as kerf render
    KerfRun r = run_kerf("watch - -o out.png", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: watch needs a scene file to watch, not standard input");
    r = run_kerf("render --watch '" + scene + "' -o -", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: watch writes a file again on each change; -o - (standard output) is not for it");
    r = run_kerf("watch '" + scene + "' --frames 3", dir);  // the farm's flags are for kerf render
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: watch renders one image on each change; --frames, --frame, --tile and "
                               "--resume are for kerf render");
    r = run_kerf("check --watch '" + scene + "'", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: unknown option '--watch'");
}
