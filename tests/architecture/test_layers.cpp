// The house as docs/architecture.md draws it: includes follow the layers
// of the pipeline, and the folder table names exactly the folders there are.
// Reads the source tree itself; links no kerf library.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const fs::path kRoot = KERF_SOURCE_DIR;
const std::vector<std::string> kSourceFolders = {"csg", "grammar", "interpreter", "lower", "render", "cli"};

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// What a folder's files may include ("x/" a whole folder, else one file).
bool allowed(const std::string& folder, const std::string& include) {
    auto in = [&](const std::string& prefix) { return include.rfind(prefix, 0) == 0; };
    if (folder == "cli") return true;
    if (in(folder + "/")) return true;
    if (folder == "interpreter") return in("grammar/") || in("csg/");
    if (folder == "lower")
        return in("csg/") || include == "grammar/source.hpp" || include == "interpreter/scene_graph.hpp";
    if (folder == "render") return in("csg/");
    return false;  // csg/, grammar/: only themselves
}

// Folders the table must list: the top-level ones (not hidden, not build
// output) and the rooms inside the source folders and stdlib/.
std::set<std::string> tree_folders() {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(kRoot)) {
        const std::string name = e.path().filename().string();
        if (!e.is_directory() || name[0] == '.' || name.rfind("build", 0) == 0) continue;
        out.insert(name + "/");
    }
    std::vector<std::string> with_rooms = kSourceFolders;
    with_rooms.push_back("stdlib");
    for (const std::string& f : with_rooms)
        for (const auto& e : fs::directory_iterator(kRoot / f))
            if (e.is_directory()) out.insert(f + "/" + e.path().filename().string() + "/");
    return out;
}

// The first column of the table under "## Folders".
std::set<std::string> table_folders() {
    std::istringstream in(read_all(kRoot / "docs/architecture.md"));
    std::set<std::string> out;
    std::string line;
    bool inside = false;
    static const std::regex row(R"(^\| `([a-z_/]+/)` \|)");
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) inside = line == "## Folders";
        std::smatch m;
        if (inside && std::regex_search(line, m, row)) out.insert(m[1]);
    }
    return out;
}

}  // namespace

TEST_CASE("includes follow the layers of docs/architecture.md", "[architecture]") {
    static const std::regex include(R"re(^\s*#\s*include\s+"([^"]+)")re");
    std::map<std::string, std::vector<std::string>> broken;
    std::size_t files = 0, edges = 0;
    for (const std::string& folder : kSourceFolders) {
        for (const auto& e : fs::recursive_directory_iterator(kRoot / folder)) {
            const std::string ext = e.path().extension().string();
            if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) continue;
            ++files;
            std::istringstream in(read_all(e.path()));
            std::string line;
            while (std::getline(in, line)) {
                std::smatch m;
                if (!std::regex_search(line, m, include)) continue;
                ++edges;
                if (!allowed(folder, m[1]))
                    broken[fs::relative(e.path(), kRoot).string()].push_back(m[1]);
            }
        }
    }
    CHECK(files > 100);
    CHECK(edges > 200);
    for (const auto& [file, includes] : broken)
        for (const std::string& inc : includes) FAIL_CHECK(file << " includes " << inc);
}

TEST_CASE("a layer check catches an edge against the pipeline", "[architecture]") {
    CHECK_FALSE(allowed("render", "interpreter/value.hpp"));
    CHECK_FALSE(allowed("csg", "render/render.hpp"));
    CHECK_FALSE(allowed("grammar", "csg/scene.hpp"));
    CHECK_FALSE(allowed("lower", "interpreter/evaluator.hpp"));
    CHECK_FALSE(allowed("interpreter", "lower/lower.hpp"));
    CHECK(allowed("lower", "interpreter/scene_graph.hpp"));
    CHECK(allowed("render", "csg/scene.hpp"));
}

TEST_CASE("docs/architecture.md's folder table matches the tree", "[architecture]") {
    const std::set<std::string> tree = tree_folders(), table = table_folders();
    CHECK(tree.size() >= 15);
    for (const std::string& f : tree)
        if (!table.count(f)) FAIL_CHECK(f << " is in the tree but not in docs/architecture.md's folder table");
    for (const std::string& f : table)
        if (!tree.count(f)) FAIL_CHECK(f << " is in docs/architecture.md's folder table but not in the tree");
}
