// Files of a run: finding what include/use/import name (the including
// file's folder, each -I folder, then kerf's stdlib/), parsing each file
// once and keeping its AST alive for the whole run (every SourceLoc and AST
// pointer the evaluator holds points into it), and the chains of files
// being included or used, so a cycle is an error naming the chain.
#pragma once
#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

#include "grammar/parser.hpp"
#include "interpreter/interpreter.hpp"

namespace kerf::eval {

class Loader {
public:
    explicit Loader(const EvalOptions& options) : opt_(options) {}

    // The path of `name` as written at `loc`; "cannot find 'name'" otherwise.
    std::string resolve(const std::string& name, const SourceLoc& loc) const;
    // A data file import(), surface(), dxf_dim() and dxf_cross() read: as
    // resolve(), but in the OpenSCAD dialect a missing file is a SoftError
    // (the caller warns and makes nothing, as OpenSCAD warns and imports
    // nothing).
    std::string resolve_data(const std::string& name, const SourceLoc& loc) const;
    // The same search; "" when no place holds `name` (an include or use the
    // OpenSCAD dialect skips with a warning).
    std::string find(const std::string& name, const SourceLoc& loc) const;
    // The parsed file at `path` (resolved), parsed on first use.
    const ast::Program& load(const std::string& path, const SourceLoc& loc);
    // One key per file, whatever the spelling (./a.sdl, d/../a.sdl, a symlink).
    static std::string identity(const std::string& path);
    // Keeps a program parsed elsewhere (the main file, -D values) alive.
    const ast::Program& keep(ast::Program program);

    // The files whose statements are being expanded (includes) or bound
    // (uses), outermost first. enter() throws "include cycle: a -> b -> a"
    // when `path` is already on the chain.
    class Chain {
    public:
        explicit Chain(const char* what) : what_(what) {}
        void enter(const std::string& path, const SourceLoc& loc);
        bool contains(const std::string& path) const;
        void leave() { paths_.pop_back(); }
        bool empty() const { return paths_.empty(); }
        // A used file's includes start a chain of their own.
        void swap(std::vector<std::string>& saved) { paths_.swap(saved); }

    private:
        const char* what_;
        std::vector<std::string> paths_;
    };
    Chain includes{"include"}, uses{"use"};
    // The OpenSCAD dialect's include chain, as OpenSCAD 2021.01 behaves
    // (measured, docs/openscad.md "Libraries"): an include is refused when
    // its spelling (the canonical folder of the including file, "/", the
    // name as written) is on the chain; the chain holds a file the main file
    // includes by its canonical path, a deeper one by its spelling, and not
    // the main file itself. So another spelling of an open file expands it
    // again (misc/include-recursive-test.scad of its test data: 16 times).
    std::vector<std::string> spelled_includes;
    std::vector<std::string> spelled_files;  // the identity of each file on that chain
    // Expansions of a file already being expanded (another spelling of it):
    // k spellings make about e·k! of them, so they are capped, an error past
    // kMaxRepeatedIncludes rather than a run that never ends.
    std::size_t repeated_includes = 0;
    static constexpr std::size_t kMaxRepeatedIncludes = 1'000;
    static std::string spelling(const std::string& including_file, const std::string& name);

private:
    const EvalOptions& opt_;
    std::deque<ast::Program> programs_;
    std::unordered_map<std::string, const ast::Program*> cache_;
};

// Leaves a chain when the scope that entered it ends, also by an exception.
struct ChainGuard {
    Loader::Chain& chain;
    ChainGuard(Loader::Chain& c, const std::string& path, const SourceLoc& loc) : chain(c) { chain.enter(path, loc); }
    ~ChainGuard() { chain.leave(); }
    ChainGuard(const ChainGuard&) = delete;
    ChainGuard& operator=(const ChainGuard&) = delete;
};

}  // namespace kerf::eval
