// A full disk while the image is written (docs/language.md §14): for every
// format the render is exit 3 naming the cause, the image it would have
// replaced keeps its bytes, and no temporary file remains. Before, BMP,
// Targa and JPEG 2000 exited 0 over a truncated file, JPEG exited 1 through
// libjpeg's exit() leaving its temporary, PNG said "out of memory".
//
// The disk is a 64 KiB tmpfs mounted for the test: that needs root (or
// CAP_SYS_ADMIN); elsewhere the tests say so and skip.
#include <catch2/catch.hpp>

#include <cerrno>
#include <cstring>
#include <set>

#include <fcntl.h>
#include <sys/mount.h>
#include <unistd.h>

#include "tests/cli/run_kerf.hpp"
#include "tests/cli/spawn_kerf.hpp"

namespace fs = std::filesystem;

namespace {

// A tmpfs of `size` on `dir` while the object lives.
struct SmallDisk {
    fs::path dir;
    bool mounted = false;
    std::string why;
    SmallDisk(const fs::path& d, const std::string& size) : dir(d) {
        fs::create_directories(dir);
        mounted = ::mount("tmpfs", dir.c_str(), "tmpfs", 0, ("size=" + size).c_str()) == 0;
        if (!mounted) why = std::strerror(errno);
    }
    ~SmallDisk() {
        if (mounted) ::umount2(dir.c_str(), MNT_DETACH);
    }
    SmallDisk(const SmallDisk&) = delete;
    SmallDisk& operator=(const SmallDisk&) = delete;
};

std::set<std::string> names_in(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

// Spheres in a row: enough detail that no format squeezes 480x360 into the
// 8 KiB left free.
const char* kScene =
    "camera(position = [3, 3, 3], look_at = [0, 0, 0]);\nlight(position = [5, -5, 10]);\n"
    "for (i = [0 : 20]) translate([i * 0.1 - 1, 0, 0]) sphere(0.3 + 0.01 * i);\n";
const std::string kOldImage = "the previous image's bytes";
constexpr std::size_t kFree = 8192;

// A test folder holding the scene and a 64 KiB disk.
struct FullDisk {
    fs::path dir;
    SmallDisk disk;
    std::string scene;
    explicit FullDisk(const std::string& name)
        : dir(test_dir(name)), disk(dir / "disk", "64k"), scene(write_file(dir / "scene.sdl", kScene)) {}

    // False, with a warning, where no tmpfs can be mounted.
    bool usable() const {
        if (!disk.mounted)
            WARN("skipped: cannot mount a 64 KiB tmpfs (" << disk.why << "); run as root to test a full disk");
        return disk.mounted;
    }
    // The disk holds old.EXT and a file filling all of it but kFree bytes.
    fs::path old_image(const std::string& ext) const {
        for (const auto& e : fs::directory_iterator(disk.dir)) fs::remove(e.path());
        const fs::path old = disk.dir / ("old." + ext);
        write_file(old, kOldImage);
        const int fd = ::open((disk.dir / "filler").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        REQUIRE(fd >= 0);
        static const char block[4096] = {};
        while (::write(fd, block, sizeof block) > 0) {
        }
        const off_t full = ::lseek(fd, 0, SEEK_END);
        REQUIRE(full > off_t(kFree));
        REQUIRE(::ftruncate(fd, full - off_t(kFree)) == 0);
        ::close(fd);
        return old;
    }
    // What the render writing `old` must have ended in.
    void check_refused(const fs::path& old, int status, const std::string& err) const {
        CHECK(status == 3);
        CHECK(err == "kerf: error: cannot write " + old.string() + ": no space left on device\n");
        CHECK(slurp(old) == kOldImage);
        CHECK(names_in(disk.dir) == std::set<std::string>{"filler", old.filename().string()});
    }
};

}  // namespace

TEST_CASE("a full disk is exit 3 naming the cause in every format, and the old image survives", "[output]") {
    const FullDisk t("disk_full");
    if (!t.usable()) return;
    const std::string size = " -W 480 -H 360 -o ";
    for (const std::string ext : {"png", "jpg", "bmp", "tga", "tif", "exr", "jp2", "sgi"}) {
        INFO("format ." << ext);
        // Where there is room the image is bigger than the space left, or
        // the test would prove nothing.
        const auto roomy = t.dir / ("roomy." + ext);
        REQUIRE(run_kerf("render '" + t.scene + "'" + size + "'" + roomy.string() + "'", t.dir).status == 0);
        REQUIRE(fs::file_size(roomy) > kFree);
        const fs::path old = t.old_image(ext);
        const KerfRun r = run_kerf("render '" + t.scene + "'" + size + "'" + old.string() + "'", t.dir);
        t.check_refused(old, r.status, r.err);
    }
}

TEST_CASE("a full disk without O_TMPFILE: the named temporary is removed too", "[output]") {
    const FullDisk t("disk_full_named");
    if (!t.usable()) return;
    for (const std::string ext : {"png", "exr"}) {
        INFO("format ." << ext);
        const fs::path old = t.old_image(ext);
        SpawnOptions no_tmpfile;
        no_tmpfile.without_tmpfile = true;
        no_tmpfile.stderr_path = (t.dir / "stderr.txt").string();
        const pid_t pid = spawn_kerf({"render", t.scene, "-W", "480", "-H", "360", "-o", old.string()}, no_tmpfile);
        REQUIRE(pid > 0);
        const int status = wait_kerf(pid);
        t.check_refused(old, status, slurp(t.dir / "stderr.txt"));
    }
}
