// read_source_file: whole files in, IoError naming path and reason out.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "grammar/parser.hpp"

namespace fs = std::filesystem;

namespace {
fs::path temp_dir() {
    fs::path dir = fs::temp_directory_path() / ("kerf_grammar_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

std::string io_error_of(const std::string& path) {
    try {
        kerf::read_source_file(path);
    } catch (const kerf::IoError& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEST_CASE("read_source_file reads the whole file", "[grammar][io]") {
    const fs::path dir = temp_dir();
    const fs::path file = dir / "scene.sdl";
    std::string text = "cube(1);\n";
    for (int i = 0; i < 20000; ++i) text += "x" + std::to_string(i) + " = " + std::to_string(i) + ";\n";
    text += std::string("\0binary\xff", 8);
    {
        std::ofstream out(file, std::ios::binary);
        out << text;
    }
    auto f = kerf::read_source_file(file.string());
    CHECK(f->path == file.string());
    CHECK(f->text == text);
    fs::remove_all(dir);
}

TEST_CASE("read_source_file errors name the path and the reason", "[grammar][io]") {
    const fs::path dir = temp_dir();
    const std::string missing = (dir / "missing.sdl").string();
    CHECK(io_error_of(missing) == "cannot open '" + missing + "': No such file or directory");
    CHECK(io_error_of(dir.string()) == "cannot open '" + dir.string() + "': Is a directory");
    if (::geteuid() != 0) {  // root reads anything
        const fs::path locked = dir / "locked.sdl";
        std::ofstream(locked) << "x = 1;";
        fs::permissions(locked, fs::perms::none);
        CHECK(io_error_of(locked.string()) == "cannot open '" + locked.string() + "': Permission denied");
    }
    fs::remove_all(dir);
}
