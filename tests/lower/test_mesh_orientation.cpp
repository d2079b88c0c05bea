// Meshes wound the wrong way render as the solid they describe: compared,
// pixel by pixel in the depth AOV, with the analytic cube they are. Before
// mesh orientation, one turned face lost that face and a reversed mesh drew
// nothing, with exit 0 and no word.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "render/render.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {

struct Rendered {
    render::Image depth;
    std::size_t warnings = 0;
};

Rendered depth_of(const std::string& solid) {
    auto f = std::make_shared<SourceFile>();
    f->path = "test.sdl";
    f->text = "camera(position = [3.1, -2.3, 2.7], look_at = [0.5, 0.5, 0.5]);\n" + solid;
    EvalResult r = evaluate_source(f);
    render::RenderOptions o;
    o.width = 48, o.height = 36, o.threads = 1, o.aov = render::Aov::Depth;
    return {render::render(lower_to_csg(r.graph), o), r.warnings.size()};
}

const std::string kPoints = "[[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1],[1,0,1],[1,1,1],[0,1,1]]";
const std::string kFaces[6] = {"[0,1,2,3]", "[4,5,1,0]", "[7,6,5,4]", "[5,6,2,1]", "[6,7,3,2]", "[7,4,0,3]"};

std::string reversed(const std::string& face) {  // "[a,b,c,d]" -> "[d,c,b,a]"
    std::string inner = face.substr(1, face.size() - 2), out;
    for (std::size_t end = inner.size(); end != std::string::npos && end > 0;) {
        const std::size_t comma = inner.rfind(',', end - 1);
        const std::size_t start = comma == std::string::npos ? 0 : comma + 1;
        out += (out.empty() ? "" : ",") + inner.substr(start, end - start);
        end = comma == std::string::npos ? 0 : comma;
    }
    return "[" + out + "]";
}

std::string polyhedron(bool (&flip)[6]) {
    std::string faces;
    for (int i = 0; i < 6; ++i) faces += (i ? "," : "") + (flip[i] ? reversed(kFaces[i]) : kFaces[i]);
    return "polyhedron(" + kPoints + ", [" + faces + "]);";
}

void same_depth(const render::Image& got, const render::Image& want) {
    test::same_depth(got, want, 1e-5);  // mesh data is float
}

}  // namespace

TEST_CASE("a polyhedron with faces wound either way renders as the cube it is") {
    const Rendered cube = depth_of("cube(1);");
    bool none[6] = {};
    const Rendered good = depth_of(polyhedron(none));
    CHECK(good.warnings == 0);
    same_depth(good.depth, cube.depth);
    for (int bad = 0; bad < 6; ++bad) {
        bool one[6] = {};
        one[bad] = true;
        INFO("face " << bad << " turned");
        const Rendered r = depth_of(polyhedron(one));
        CHECK(r.warnings == 1);
        same_depth(r.depth, cube.depth);
    }
    bool all[6] = {true, true, true, true, true, true};
    const Rendered r = depth_of(polyhedron(all));
    CHECK(r.warnings == 1);
    same_depth(r.depth, cube.depth);
}

TEST_CASE("an open polyhedron renders as a shell: its faces are where the solid's are") {
    // The missing face (the bottom, z = 0) is turned away from the camera,
    // so the shell shows what the closed cube shows.
    const Rendered cube = depth_of("cube(1);");
    const Rendered open = depth_of("polyhedron(" + kPoints + ", [" + kFaces[1] + "," + kFaces[2] + "," + kFaces[3] +
                                   "," + kFaces[4] + "," + kFaces[5] + "]);");
    CHECK(open.warnings == 1);
    same_depth(open.depth, cube.depth);
}
