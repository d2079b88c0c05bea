#include "interpreter/loader.hpp"

#include "interpreter/value.hpp"

#include <cstdlib>
#include <filesystem>

#ifndef KERF_STDLIB_DIR
#define KERF_STDLIB_DIR ""
#endif

namespace kerf::eval {

namespace fs = std::filesystem;

std::string Loader::identity(const std::string& path) {
    std::error_code ec;
    auto c = fs::weakly_canonical(path, ec);
    return ec ? path : c.string();
}

std::string Loader::spelling(const std::string& including_file, const std::string& name) {
    return fs::path(identity(including_file)).parent_path().string() + "/" + name;
}

std::string Loader::resolve(const std::string& name_text, const SourceLoc& loc) const {
    std::string path = find(name_text, loc);
    if (path.empty()) throw SourceError(loc, "cannot find '" + name_text + "'");
    return path;
}

std::string Loader::resolve_data(const std::string& name_text, const SourceLoc& loc) const {
    std::string path = find(name_text, loc);
    if (!path.empty()) return path;
    if (opt_.dialect == Dialect::Lenient) throw SoftError(loc, "cannot find '" + name_text + "'");
    throw SourceError(loc, "cannot find '" + name_text + "'");
}

std::string Loader::find(const std::string& name_text, const SourceLoc& loc) const {
    fs::path name(name_text);
    std::vector<fs::path> dirs;
    if (name.is_absolute()) {
        dirs.push_back(fs::path());
    } else {
        fs::path base = loc.file ? fs::path(loc.file->path).parent_path() : fs::path();
        dirs.push_back(base.empty() ? fs::path(".") : base);
        for (const std::string& d : opt_.include_dirs) dirs.emplace_back(d);
        std::string stdlib = opt_.stdlib_dir.empty() ? std::string(KERF_STDLIB_DIR) : opt_.stdlib_dir;
        if (!stdlib.empty()) dirs.emplace_back(stdlib);
        if (opt_.dialect == Dialect::Lenient) {
            // OpenSCAD's library search: OPENSCADPATH, the user's library
            // folder, the installed libraries (Debian's MCAD).
            if (const char* env = std::getenv("OPENSCADPATH")) {
                std::string list = env;
                for (std::size_t start = 0; start <= list.size();) {
                    std::size_t colon = list.find(':', start);
                    if (colon == std::string::npos) colon = list.size();
                    if (colon > start) dirs.emplace_back(list.substr(start, colon - start));
                    start = colon + 1;
                }
            }
            if (const char* home = std::getenv("HOME")) dirs.emplace_back(fs::path(home) / ".local/share/OpenSCAD/libraries");
            dirs.emplace_back("/usr/share/openscad/libraries");
        }
    }
    for (const fs::path& d : dirs) {
        fs::path p = d.empty() ? name : d / name;
        std::error_code ec;
        if (opt_.on_dependency) opt_.on_dependency(p.lexically_normal().string());
        if (fs::is_regular_file(p, ec)) return p.lexically_normal().string();
    }
    return {};
}

const ast::Program& Loader::load(const std::string& path, const SourceLoc& loc) {
    auto it = cache_.find(path);
    if (it != cache_.end()) return *it->second;
    std::shared_ptr<const SourceFile> file;
    try {
        file = read_source_file(path);
    } catch (const IoError& e) {
        throw SourceError(loc, e.what());
    }
    ParseOptions pl;
    pl.max_nesting = opt_.limits.nesting;
    pl.openscad = opt_.dialect == Dialect::Lenient;
    const ast::Program& p = keep(parse_program(std::move(file), pl));
    cache_[path] = &p;
    return p;
}

const ast::Program& Loader::keep(ast::Program program) {
    programs_.push_back(std::move(program));
    return programs_.back();
}

bool Loader::Chain::contains(const std::string& path) const {
    const std::string key = identity(path);
    for (const std::string& c : paths_)
        if (identity(c) == key) return true;
    return false;
}

void Loader::Chain::enter(const std::string& path, const SourceLoc& loc) {
    if (contains(path)) {
        std::string text;
        for (const std::string& p : paths_) text += p + " -> ";
        throw SourceError(loc, std::string(what_) + " cycle: " + text + path);
    }
    paths_.push_back(path);
}

}  // namespace kerf::eval
