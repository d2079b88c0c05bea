// The `kerf dump` text format (docs/dump-format.md), on a scene whose
// lowered form is known by hand.
#include <catch2/catch.hpp>

#include "tests/lower/graph_builder.hpp"
#include "tests/lower/script_scene.hpp"
#include "lower/lower.hpp"
#include "csg/dump.hpp"

#include <sstream>

using namespace kerf;
using kerf::test::GraphBuilder;

namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') {
            out.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    return out;
}

}  // namespace

TEST_CASE("dump prints header, scene set-up and the indented tree") {
    GraphBuilder b;
    b.next_line = 3;
    const auto s1 = b.sphere(1);                              // line 3
    const auto c = b.translate({0.5, 0, 0}, b.cube(1));       // cube line 4
    const auto d = b.diff({s1, c});
    b.g.background = glm::dvec3(0, 0, 0.5);
    const std::string text = csg::dump_scene(lower_to_csg(b.finish({d, b.translate({5, 0, 0}, b.torus(1, 0.25))})));
    const auto l = lines(text);
    REQUIRE(l.size() >= 6);
    CHECK(l[0] == "kerf-dump 1");
    CHECK(l[1] == "scene leaves=3 nodes=5 materials=1 meshes=0");
    CHECK(l[2].rfind("camera perspective position=[", 0) == 0);
    CHECK(l[3].rfind("light point position=", 0) == 0);
    CHECK(l[4].rfind("light point position=", 0) == 0);
    CHECK(l[5] == "background color=[0 0 0.5]");
    CHECK(l[6] == "ground z=-1 shadow=0.6");  // the studio look's shadow catcher: not in the tree
    CHECK(l[7] == "material 0 color=[0.8 0.8 0.8] interior=[0.8 0.8 0.8] diffuse=0.8 specular=0.2 shininess=32 reflect=0");
    CHECK(l[8] == "tree");
    CHECK(l[9] == "union children=2 lo=[-1 -1.25 -1] hi=[6.25 1.25 1]");
    CHECK(l[10] == "  difference children=2 lo=[-1 -1 -1] hi=[1 1 1]");
    CHECK(l[11] == "    sphere r=1 leaf=0 material=0 lo=[-1 -1 -1] hi=[1 1 1] world=[1 0 0 0 | 0 1 0 0 | 0 0 1 0] at=test.sdl:3:1");
    CHECK(l[12] == "    box min=[0 0 0] max=[1 1 1] leaf=1 material=0 lo=[0.5 0 0] hi=[1.5 1 1] world=[1 0 0 0.5 | 0 1 0 0 | 0 0 1 0] at=test.sdl:4:1");
    CHECK(l[13].rfind("  torus R=1 r=0.25 leaf=2 material=0 lo=[3.75 -1.25 -0.25] hi=[6.25 1.25 0.25]", 0) == 0);
    CHECK(l.size() == 14);
}

TEST_CASE("dump of an empty scene and of half-spaces") {
    GraphBuilder b;
    CHECK(csg::dump_scene(lower_to_csg(b.finish({}))).find("\ntree empty\n") != std::string::npos);
    GraphBuilder b2;
    const std::string text = csg::dump_scene(lower_to_csg(b2.finish({b2.plane({0, 0, 1}, 0)})));
    CHECK(text.find("plane normal=[0 0 1] offset=0 leaf=0 material=0 lo=[-inf -inf -inf] hi=[inf inf 0]") != std::string::npos);
}

TEST_CASE("the streamed dump is the same text") {
    GraphBuilder b;
    std::vector<std::uint32_t> many;
    for (int i = 0; i < 2000; ++i) many.push_back(b.translate({3.0 * i, 0, 0}, b.sphere(1)));
    const csg::Scene s = lower_to_csg(b.finish(many));
    std::ostringstream os;
    csg::dump_scene(s, os);
    CHECK(os.str() == csg::dump_scene(s));
    CHECK(os.str().size() > (1u << 17));  // long enough to be flushed in pieces
}

TEST_CASE("dump prints the ghosts of % and # after the solid, each under its own header") {
    // A `%` cube is no solid; a `#` sphere is in the solid and drawn once more in pink (docs/openscad.md, "Modifiers").
    const csg::Scene s = test::lowered_as("%translate([3, 0, 0]) cube(1);\n#sphere(1);\n", "test.scad");
    const auto l = lines(csg::dump_scene(s));
    const auto at = [&](const std::string& head) {
        for (std::size_t i = 0; i < l.size(); ++i)
            if (l[i] == head) return i;
        return l.size();
    };
    const std::size_t tree = at("tree"), bg = at("ghost background leaves=1 nodes=1 materials=2 meshes=0"),
                      hi = at("ghost highlight leaves=1 nodes=1 materials=1 meshes=0");
    REQUIRE(tree < bg);
    REQUIRE(bg < hi);
    REQUIRE(hi + 3 < l.size());
    CHECK(l[1] == "scene leaves=1 nodes=1 materials=1 meshes=0");  // the solid: the sphere alone
    CHECK(l[tree + 1].rfind("sphere r=1 leaf=0 material=0 lo=[-1 -1 -1] hi=[1 1 1]", 0) == 0);
    CHECK(bg == tree + 2);
    // Each ghost: its materials (OpenSCAD's preview grey, translucent: transparency 1 − 128/255, after the
    // default), its tree, its leaf where it is drawn.
    CHECK(l[bg + 1].rfind("material 0 ", 0) == 0);
    CHECK(l[bg + 2].rfind("material 1 color=[0.456411 0.456411 0.456411] ", 0) == 0);
    CHECK(l[bg + 2].find(" transparency=0.498039") != std::string::npos);
    CHECK(l[bg + 3] == "tree");
    CHECK(l[bg + 4].rfind("box min=[0 0 0] max=[1 1 1] leaf=0 material=1 lo=[3 0 0] hi=[4 1 1] world=[1 0 0 3 | 0 1 0 0 | 0 0 1 0] at=test.scad:1:", 0) == 0);
    CHECK(l[hi + 1].rfind("material 0 color=[1 ", 0) == 0);  // OpenSCAD's highlight pink: full red
    CHECK(l[hi + 2] == "tree");
    CHECK(l[hi + 3].rfind("sphere r=1 leaf=0 material=0 lo=[-1 -1 -1] hi=[1 1 1]", 0) == 0);
    CHECK(hi + 4 == l.size());
    // --no-ghosts (and kerf measure): none lowered, none printed.
    LowerOptions none;
    none.ghosts = false;
    CHECK(csg::dump_scene(lower_to_csg(test::evaluated("%cube(1);\nsphere(1);\n", "test.scad").graph, none)).find("ghost") ==
          std::string::npos);
}
