// Solids, transforms and appearance (docs/spec.md §4–§5): canonical parameters,
// matrices checked against closed-form values, located errors.
#include <catch2/catch.hpp>

#include <cmath>

#include "tests/interpreter/eval_helpers.hpp"

using kerf::csg::PrimKind;
using kerf::test::error_of;
using kerf::test::leaves_of;
using kerf::test::shape_of;

namespace {
kerf::test::Leaf one(const std::string& src) {
    auto l = leaves_of(src);
    REQUIRE(l.size() == 1);
    return l[0];
}
std::vector<double> params(const std::string& src, std::size_t n) {
    auto l = one(src);
    return std::vector<double>(l.p.begin(), l.p.begin() + static_cast<long>(n));
}
glm::dvec3 apply(const glm::dmat4& m, glm::dvec3 p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }
bool near(glm::dvec3 a, glm::dvec3 b) { return glm::length(a - b) < 1e-12; }
}  // namespace

TEST_CASE("sphere", "[solids]") {
    CHECK(params("sphere();", 1) == std::vector<double>{1});
    CHECK(params("sphere(2);", 1) == std::vector<double>{2});
    CHECK(params("sphere(d = 3);", 1) == std::vector<double>{1.5});
    CHECK(params("sphere(r = 4, $fn = 100);", 1) == std::vector<double>{4});
    CHECK(one("sphere();").prim == PrimKind::Sphere);
    CHECK(error_of("sphere(0);") == "test.sdl:1:1: error: sphere: radius must be positive, got 0");
    CHECK(error_of("sphere(-1);") == "test.sdl:1:1: error: sphere: radius must be positive, got -1");
    CHECK(error_of("sphere(r = 1, d = 2);") == "test.sdl:1:1: error: sphere: give r or d, not both");
    CHECK(error_of("sphere(\"a\");") == "test.sdl:1:1: error: sphere: r must be a number, got \"a\"");
    CHECK(error_of("sphere(0/0);") == "test.sdl:1:1: error: sphere: r must be finite, got nan");
    CHECK(error_of("sphere(1, 2, 3);") == "test.sdl:1:14: error: too many arguments for 'sphere' (takes 2)");
    CHECK(error_of("sphere(radius = 1);") == "test.sdl:1:8: error: unknown argument 'radius' for 'sphere'");
    CHECK(error_of("sphere(undef);") == "test.sdl:1:1: error: sphere: r must be a number, got undef");
}

TEST_CASE("cube", "[solids]") {
    CHECK(params("cube();", 6) == std::vector<double>{0, 0, 0, 1, 1, 1});
    CHECK(params("cube(2);", 6) == std::vector<double>{0, 0, 0, 2, 2, 2});
    CHECK(params("cube([1, 2, 3], center = true);", 6) == std::vector<double>{-0.5, -1, -1.5, 0.5, 1, 1.5});
    CHECK(params("cube(center = true, size = [4, 2, 2]);", 6) == std::vector<double>{-2, -1, -1, 2, 1, 1});
    CHECK(one("cube();").prim == PrimKind::Box);
    CHECK(error_of("cube([1, 0, 1]);") == "test.sdl:1:1: error: cube: size must be positive, got 0");
    CHECK(error_of("cube([1, 1]);") == "test.sdl:1:1: error: cube: size must be a vector of 3 numbers, got [1, 1]");
    CHECK(error_of("cube(1, center = 1);") == "test.sdl:1:1: error: cube: center must be true or false, got 1");
}

TEST_CASE("cylinder and cone", "[solids]") {
    CHECK(params("cylinder();", 4) == std::vector<double>{0, 1, 1, 1});
    CHECK(params("cylinder(h = 4, r = 2, center = true);", 4) == std::vector<double>{-2, 2, 2, 2});
    CHECK(params("cylinder(3, 1, 0);", 4) == std::vector<double>{0, 3, 1, 0});
    CHECK(params("cylinder(h = 2, d1 = 4, d2 = 2);", 4) == std::vector<double>{0, 2, 2, 1});
    CHECK(params("cylinder(h = 2, d = 6);", 4) == std::vector<double>{0, 2, 3, 3});
    CHECK(params("cylinder(h = 2, r1 = 2);", 4) == std::vector<double>{0, 2, 2, 1});
    CHECK(params("cone(h = 2, r = 3);", 4) == std::vector<double>{0, 2, 3, 0});
    CHECK(params("cone(4, 1, center = true);", 4) == std::vector<double>{-2, 2, 1, 0});
    CHECK(one("cone();").prim == PrimKind::Cylinder);
    CHECK(error_of("cylinder(h = 0);") == "test.sdl:1:1: error: cylinder: h must be positive, got 0");
    CHECK(error_of("cylinder(r1 = 0, r2 = 0);") == "test.sdl:1:1: error: cylinder: radius must be positive, got 0");
    CHECK(error_of("cylinder(r = -1);") == "test.sdl:1:1: error: cylinder: radius must not be negative, got -1");
    CHECK(error_of("cylinder(r = 1, r1 = 2);") == "test.sdl:1:1: error: cylinder: give r/d or r1/r2/d1/d2, not both");
    CHECK(error_of("cylinder(d2 = 1, r2 = 2);") == "test.sdl:1:1: error: cylinder: give r2 or d2, not both");
    CHECK(error_of("cone(r = 0);") == "test.sdl:1:1: error: cone: radius must be positive, got 0");
}

TEST_CASE("torus, plane, paraboloid, hyperboloid", "[solids]") {
    CHECK(params("torus();", 2) == std::vector<double>{1, 0.25});
    CHECK(params("torus(3, 1);", 2) == std::vector<double>{3, 1});
    CHECK(error_of("torus(1, 1);") == "test.sdl:1:1: error: torus: minor radius r must be smaller than R, got r = 1, R = 1");
    CHECK(error_of("torus(R = 0);") == "test.sdl:1:1: error: torus: R must be positive, got 0");
    CHECK(params("plane();", 4) == std::vector<double>{0, 0, 1, 0});
    // The normal is normalised and the offset scaled with it: same half-space.
    CHECK(params("plane([0, 3, 4], 10);", 4) == std::vector<double>{0, 0.6, 0.8, 2});
    CHECK(error_of("plane([0, 0, 0]);") == "test.sdl:1:1: error: plane: normal must not be zero");
    CHECK(params("paraboloid(2, 3);", 2) == std::vector<double>{2, 3});
    CHECK(params("hyperboloid(h = 2, r = 1, waist = 0.25);", 3) == std::vector<double>{2, 1, 0.25});
    CHECK(params("hyperboloid();", 3) == std::vector<double>{1, 1, 0.5});
    CHECK(error_of("hyperboloid(waist = 2);") == "test.sdl:1:1: error: hyperboloid: waist must be smaller than r, got waist = 2, r = 1");
    CHECK(error_of("paraboloid(r = -2);") == "test.sdl:1:1: error: paraboloid: r must be positive, got -2");
}

TEST_CASE("polyhedron", "[solids]") {
    const char* tetra =
        "polyhedron(points = [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], faces = [[0,1,2],[0,3,1],[0,2,3],[1,3,2]]);";
    auto r = kerf::test::run(tetra);
    REQUIRE(r.graph.meshes.size() == 1);
    CHECK(r.graph.meshes[0].points.size() == 4);
    CHECK(r.graph.meshes[0].faces[1] == std::vector<std::uint32_t>{0, 3, 1});
    auto l = kerf::test::leaves(r.graph);
    REQUIRE(l.size() == 1);
    CHECK(l[0].prim == PrimKind::Mesh);
    CHECK(l[0].index == 0);
    CHECK(error_of("polyhedron(points = [[0,0,0],[1,0,0],[0,1,0],[0,0,1]], faces = [[0,1,2],[0,3,1],[0,2,3],[1,3,9]]);") ==
          "test.sdl:1:1: error: polyhedron: face 3 refers to point 9 (there are 4 points)");
    CHECK(error_of("polyhedron(points = [[0,0]], faces = []);") ==
          "test.sdl:1:1: error: polyhedron: points must be a list of [x, y, z] points, got an element [0, 0]");
    CHECK(error_of("import(\"a.stl\");") == "test.sdl:1:1: error: cannot find 'a.stl'");
}

TEST_CASE("translate, scale, mirror, multmatrix", "[transforms]") {
    auto l = one("translate([1, 2, 3]) sphere();");
    CHECK(near(apply(l.world, {0, 0, 0}), {1, 2, 3}));
    l = one("translate([1, 2]) sphere();");
    CHECK(near(apply(l.world, {0, 0, 0}), {1, 2, 0}));
    l = one("scale(2) sphere();");
    CHECK(near(apply(l.world, {1, 1, 1}), {2, 2, 2}));
    l = one("scale([1, -1, 3]) sphere();");
    CHECK(near(apply(l.world, {1, 1, 1}), {1, -1, 3}));
    // mirror([1, 1, 0]): reflection across the plane x + y = 0.
    l = one("mirror([1, 1, 0]) sphere();");
    CHECK(near(apply(l.world, {1, 0, 0}), {0, -1, 0}));
    CHECK(near(apply(l.world, {0, 0, 5}), {0, 0, 5}));
    l = one("multmatrix([[1, 0, 0, 5], [0, 2, 0, 6], [0, 0, 1, 7]]) sphere();");
    CHECK(near(apply(l.world, {1, 1, 1}), {6, 8, 8}));
    l = one("multmatrix([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) sphere();");
    CHECK(near(apply(l.world, {1, 0, 0}), {0, 1, 0}));
    // translate(t) rotate(r) s: rotate first, then translate.
    l = one("translate([10, 0, 0]) rotate(90) sphere();");
    CHECK(near(apply(l.world, {1, 0, 0}), {10, 1, 0}));
    CHECK(error_of("scale([1, 0, 1]) sphere();") == "test.sdl:1:1: error: scale: factor must not be 0");
    CHECK(error_of("mirror([0, 0, 0]) sphere();") == "test.sdl:1:1: error: mirror: normal v must not be zero");
    CHECK(error_of("translate(\"x\") sphere();") == "test.sdl:1:1: error: translate: v must be a vector of 2 or 3 numbers, got \"x\"");
    CHECK(error_of("translate([1/0, 0, 0]) sphere();") == "test.sdl:1:1: error: translate: v must be finite, got [inf, 0, 0]");
    CHECK(error_of("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, 1]]) sphere();") ==
          "test.sdl:1:1: error: multmatrix: the last row must be [0, 0, 0, 1] (only affine transforms are supported)");
    CHECK(error_of("multmatrix([[1, 0], [0, 1]]) sphere();") == "test.sdl:1:1: error: multmatrix: m must be a 4x4 or 3x4 matrix of numbers");
}

TEST_CASE("rotate: three forms, degrees, X then Y then Z", "[transforms]") {
    auto l = one("rotate(90) sphere();");
    CHECK(apply(l.world, {1, 0, 0}) == glm::dvec3(0, 1, 0));  // exact at multiples of 90
    l = one("rotate([90, 0, 0]) sphere();");
    CHECK(apply(l.world, {0, 1, 0}) == glm::dvec3(0, 0, 1));
    l = one("rotate([0, 90, 0]) sphere();");
    CHECK(apply(l.world, {0, 0, 1}) == glm::dvec3(1, 0, 0));
    // X first, then Z: the Y axis goes to +Z under X(90) and stays there under Z(90).
    l = one("rotate([90, 0, 90]) sphere();");
    CHECK(near(apply(l.world, {0, 1, 0}), {0, 0, 1}));
    CHECK(near(apply(l.world, {1, 0, 0}), {0, 1, 0}));
    // Axis-angle: 120° about [1,1,1] cycles the axes.
    l = one("rotate(a = 120, v = [1, 1, 1]) sphere();");
    CHECK(near(apply(l.world, {1, 0, 0}), {0, 1, 0}));
    l = one("rotate(30) sphere();");
    CHECK(near(apply(l.world, {1, 0, 0}), {std::sqrt(3.0) / 2, 0.5, 0}));
    CHECK(error_of("rotate([1, 2], [0, 0, 1]) sphere();") == "test.sdl:1:1: error: rotate: v is only allowed with a single angle");
    CHECK(error_of("rotate(45, [0, 0, 0]) sphere();") == "test.sdl:1:1: error: rotate: axis v must not be zero");
}

TEST_CASE("rotate() and a multmatrix written with sin()/cos() are the same solid, bit for bit", "[transforms]") {
    // One sin_deg for rotate() and the built-ins: they used to disagree in
    // the last bit at 45°, 30°, 75°, 120°, 225°... (two copies of it).
    for (const std::string deg : {"45", "30", "75", "120", "225", "12", "22.5", "60", "-45", "405", "1000.5"}) {
        const auto r = one("rotate(" + deg + ") sphere();");
        const auto m = one("a = " + deg + "; multmatrix([[cos(a), -sin(a), 0, 0], [sin(a), cos(a), 0, 0], [0, 0, 1, 0]]) sphere();");
        INFO("angle " << deg);
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 4; ++k) CHECK(r.world[c][k] == m.world[c][k]);
    }
}

TEST_CASE("booleans and transform grouping", "[transforms]") {
    CHECK(shape_of("difference() { cube(); sphere(); cylinder(); }") == "U(D(box,sphere,cylinder))");
    CHECK(shape_of("intersection() { cube(); sphere(); }") == "U(I(box,sphere))");
    CHECK(shape_of("difference() {}") == "U(D())");
    CHECK(shape_of("translate([1, 0, 0]) { cube(); sphere(); }") == "U(T(U(box,sphere)))");
    CHECK(shape_of("translate([1, 0, 0]) {}") == "U()");
    CHECK(error_of("union(1) cube();") == "test.sdl:1:7: error: too many arguments for 'union' (takes 0)");
    auto l = leaves_of("translate([1, 0, 0]) scale(2) { sphere(); translate([0, 1, 0]) cube(); }");
    REQUIRE(l.size() == 2);
    CHECK(near(apply(l[0].world, {1, 0, 0}), {3, 0, 0}));
    CHECK(near(apply(l[1].world, {0, 0, 0}), {1, 2, 0}));
}

TEST_CASE("color and material", "[appearance]") {
    auto l = one("color([1, 0, 0]) sphere();");
    REQUIRE(l.has_material);
    CHECK(l.material.color == glm::dvec3(1, 0, 0));
    CHECK(l.material.interior == glm::dvec3(1, 0, 0));
    CHECK(l.material.transparency == 0);
    l = one("color([0, 1, 0, 0.5]) sphere();");
    CHECK(l.material.transparency == 0.5);
    l = one("color(\"red\", alpha = 0.25) sphere();");
    CHECK(l.material.color == glm::dvec3(1, 0, 0));
    CHECK(l.material.transparency == 0.75);
    l = one("color(\"#ff8000\") sphere();");
    // Colours are sRGB as written and stored linear (docs/language.md §10):
    // 128/255 decodes to ((128/255 + 0.055) / 1.055)^2.4.
    CHECK(l.material.color.r == 1);
    CHECK(l.material.color.g == Approx(std::pow((128 / 255.0 + 0.055) / 1.055, 2.4)).epsilon(1e-12));
    CHECK(l.material.color.b == 0);
    // The innermost colour wins.
    l = one("color(\"red\") color(\"blue\") sphere();");
    CHECK(l.material.color == glm::dvec3(0, 0, 1));
    l = one("material(color = [0, 0, 1], interior = [1, 1, 0], specular = 0.9, shininess = 100, reflect = 0.5) sphere();");
    CHECK(l.material.color == glm::dvec3(0, 0, 1));
    CHECK(l.material.interior == glm::dvec3(1, 1, 0));
    CHECK(l.material.specular == 0.9);
    CHECK(l.material.shininess == 100);
    CHECK(l.material.reflect == 0.5);
    CHECK(l.material.diffuse == 0.8);
    // color() inside material() keeps the material's other parameters.
    l = one("material(specular = 1) color([0, 1, 0]) sphere();");
    CHECK(l.material.specular == 1);
    CHECK(l.material.color == glm::dvec3(0, 1, 0));
    CHECK(one("sphere();").has_material == false);
    CHECK(error_of("color(\"nosuchcolour\") sphere();") == "test.sdl:1:1: error: color: unknown colour name \"nosuchcolour\"");
    CHECK(error_of("color([255, 0, 0]) sphere();") == "test.sdl:1:1: error: color: c components must be in [0, 1], got [255, 0, 0]");
    // Glass and glow (docs/language.md, "Glass").
    l = one("material(transparency = 0.9, ior = 1.5, absorption = [0.1, 0.2, 0.3], roughness = 0.25) sphere();");
    CHECK(l.material.transparency == 0.9);
    CHECK(l.material.ior == 1.5);
    CHECK(l.material.absorption == glm::dvec3(0.1, 0.2, 0.3));
    CHECK(l.material.roughness == 0.25);
    CHECK(one("material(absorption = 2) sphere();").material.absorption == glm::dvec3(2));
    CHECK(one("material(color = [1, 0, 0], emission = 2) sphere();").material.emission == glm::dvec3(2, 0, 0));
    CHECK(one("material(emission = [0, 0, 1]) sphere();").material.emission == glm::dvec3(0, 0, 1));
    // An inner color() keeps the glass, and its alpha sets the transparency.
    l = one("material(ior = 1.33, transparency = 0.8) color(\"blue\", alpha = 0.4) sphere();");
    CHECK(l.material.ior == 1.33);
    CHECK(l.material.transparency == Approx(0.6));
    CHECK(error_of("material(ior = 0) sphere();") == "test.sdl:1:1: error: material: ior must be in (0, 10], got 0");
    CHECK(error_of("material(ior = 11) sphere();") == "test.sdl:1:1: error: material: ior must be in (0, 10], got 11");
    CHECK(error_of("material(transparency = 1.5) sphere();") ==
          "test.sdl:1:1: error: material: transparency must be in [0, 1], got 1.5");
    CHECK(error_of("material(absorption = -1) sphere();") ==
          "test.sdl:1:1: error: material: absorption must not be negative, got -1");
    CHECK(error_of("material(emission = -1) sphere();") ==
          "test.sdl:1:1: error: material: emission must not be negative, got -1");
    CHECK(error_of("material(roughness = 2) sphere();") == "test.sdl:1:1: error: material: roughness must be in [0, 1], got 2");
    CHECK(error_of("material(glow = 1) sphere();").find("glow") != std::string::npos);
    CHECK(error_of("material(diffuse = 2) sphere();") == "test.sdl:1:1: error: material: diffuse must be in [0, 1], got 2");
}

TEST_CASE("scene statements only at top level", "[scene]") {
    auto r = kerf::test::run(
        "camera(position = [10, 0, 5], look_at = [0, 0, 1], fov = 30);\n"
        "light(position = [5, 5, 5], intensity = 0.5);\n"
        "light(direction = [0, 0, -2], color = \"white\");\n"
        "background([0.1, 0.2, 0.3]);\n"
        "sphere();");
    REQUIRE(r.graph.camera.has_value());
    CHECK(r.graph.camera->position == glm::dvec3(10, 0, 5));
    CHECK(r.graph.camera->look_at == glm::dvec3(0, 0, 1));
    CHECK(r.graph.camera->fov == 30);
    CHECK_FALSE(r.graph.camera->orthographic);
    REQUIRE(r.graph.lights.size() == 2);
    CHECK(r.graph.lights[0].position == glm::dvec3(5, 5, 5));
    CHECK(r.graph.lights[0].intensity == 0.5);
    CHECK(r.graph.lights[1].directional);
    CHECK(r.graph.lights[1].direction == glm::dvec3(0, 0, -1));
    REQUIRE(r.graph.background.has_value());
    auto decode = [](double c) { return std::pow((c + 0.055) / 1.055, 2.4); };
    CHECK(r.graph.background->r == Approx(decode(0.1)).epsilon(1e-12));
    CHECK(r.graph.background->g == Approx(decode(0.2)).epsilon(1e-12));
    CHECK(r.graph.background->b == Approx(decode(0.3)).epsilon(1e-12));
    auto o = kerf::test::run("camera(position = [0, -5, 0], projection = \"orthographic\", height = 4);");
    CHECK(o.graph.camera->orthographic);
    CHECK(o.graph.camera->height == 4);
    CHECK(error_of("module m() camera(position = [1, 1, 1]);\nm();") ==
          "test.sdl:1:12: error: camera is only allowed at the top level");
    CHECK(error_of("if (true) light(position = [1, 1, 1]);") == "test.sdl:1:11: error: light is only allowed at the top level");
    CHECK(error_of("translate([1, 0, 0]) background([0, 0, 0]);") == "test.sdl:1:22: error: background is only allowed at the top level");
    CHECK(error_of("camera(position = [1, 1, 1]);\ncamera(position = [2, 2, 2]);") ==
          "test.sdl:2:1: error: camera is already defined at line 1");
    CHECK(error_of("camera(position = [0, 0, 5]);") == "test.sdl:1:1: error: camera: up must not be parallel to the view direction");
    CHECK(error_of("light(position = [1, 1, 1], direction = [0, 0, 1]);") == "test.sdl:1:1: error: light: give position or direction (exactly one)");
}

TEST_CASE("the scene graph lists children before parents", "[scene]") {
    auto r = kerf::test::run("difference() { cube(); translate([1, 1, 1]) color(\"red\") sphere(); }\nfor (i = [0:3]) cube();");
    const auto& g = r.graph;
    CHECK(g.root == g.nodes.size() - 1);
    CHECK(g.nodes[g.root].kind == kerf::graph::NodeKind::Union);
    for (std::uint32_t id = 0; id < g.nodes.size(); ++id)
        for (std::uint32_t i = 0; i < g.nodes[id].child_count; ++i) CHECK(g.child_refs[g.nodes[id].first_child + i] < id);
    CHECK(g.nodes[0].loc.line == 1);
}

// OpenSCAD's precedence in the .scad dialect: d over r, then r1/r2 over r.
// Expected radii measured from OpenSCAD 2021's own STL: for each argument
// list, `echo 'cylinder(h=1, ARGS, $fn=64);' > cy.scad; openscad -o cy.stl cy.scad`
// and the largest vertex radius at z = 0 and z = 1.
TEST_CASE("cylinder given r with r1/r2/d in the OpenSCAD dialect", "[solids][openscad]") {
    auto radii = [](const std::string& args) {
        kerf::EvalOptions opt;
        opt.dialect = kerf::Dialect::Lenient;
        opt.echo = [](const std::string&) {};
        auto r = kerf::evaluate_source(kerf::test::source("cylinder(h = 1, " + args + ");", "test.scad"), opt);
        auto l = kerf::test::leaves(r.graph);
        REQUIRE(l.size() == 1);
        REQUIRE(r.warnings.size() == 1);
        return std::vector<double>{l[0].p[2], l[0].p[3]};
    };
    CHECK(radii("r = 2, r1 = 1") == std::vector<double>{1, 2});           // Cylinder parameters ambiguous
    CHECK(radii("r = 2, d = 2") == std::vector<double>{1, 1});            // Ignoring radius variable 'r' ...
    CHECK(radii("r1 = 1, d1 = 6") == std::vector<double>{3, 1});
    CHECK(radii("d = 4, r2 = 3") == std::vector<double>{2, 3});
    CHECK(radii("r = 2, r2 = 3, d1 = 1") == std::vector<double>{0.5, 3});
}
