// Helpers for interpreter tests: evaluate a script held in memory, capture
// its echo lines or its first error, and read the scene graph back through
// an independent walker (world matrix and material per primitive).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "interpreter/interpreter.hpp"

namespace kerf::test {

inline std::shared_ptr<const SourceFile> source(const std::string& text, const std::string& path = "test.sdl") {
    auto f = std::make_shared<SourceFile>();
    f->path = path;
    f->text = text;
    return f;
}

inline EvalResult run(const std::string& text, EvalOptions opt = {}) {
    if (!opt.echo) opt.echo = [](const std::string&) {};
    return evaluate_source(source(text), opt);
}

// The echo lines a script prints (it must evaluate without error).
inline std::vector<std::string> echoes(const std::string& text, EvalOptions opt = {}) {
    std::vector<std::string> lines;
    opt.echo = [&](const std::string& l) { lines.push_back(l); };
    evaluate_source(source(text), opt);
    return lines;
}

// The single echo line of `echo(expr)`, without "ECHO: ".
inline std::string value_of(const std::string& expr, const std::string& prelude = "") {
    auto lines = echoes(prelude + "\necho(" + expr + ");\n");
    if (lines.size() != 1) return "<" + std::to_string(lines.size()) + " echo lines>";
    return lines[0].substr(6);
}

// "PATH:LINE:COL: error: MESSAGE" of the first error, or "no error".
inline std::string error_of(const std::string& text, EvalOptions opt = {}) {
    try {
        run(text, std::move(opt));
    } catch (const SourceError& e) {
        return format_diagnostic_head(e.diagnostic());
    }
    return "no error";
}

struct Leaf {
    csg::PrimKind prim;
    std::vector<double> p;
    glm::dmat4 world{1.0};
    csg::Material material;
    bool has_material = false;
    std::uint32_t index = 0;
};

// Every primitive reachable from the root, with the product of the
// transforms above it and the innermost appearance.
inline void collect(const graph::SceneGraph& g, std::uint32_t id, const glm::dmat4& m, const csg::Material* mat,
                    std::vector<Leaf>& out) {
    const graph::Node& n = g.nodes.at(id);
    switch (n.kind) {
        case graph::NodeKind::Primitive: {
            Leaf l{n.prim, std::vector<double>(n.p, n.p + 6), m, mat ? *mat : csg::Material{}, mat != nullptr,
                   n.index};
            out.push_back(l);
            return;
        }
        case graph::NodeKind::Transform:
            collect(g, g.child_refs.at(n.first_child), m * g.matrices.at(n.index), mat, out);
            return;
        case graph::NodeKind::Appearance:
            collect(g, g.child_refs.at(n.first_child), m, &g.materials.at(n.index), out);  // innermost wins
            return;
        default:
            for (std::uint32_t i = 0; i < n.child_count; ++i) collect(g, g.child_refs.at(n.first_child + i), m, mat, out);
    }
}

inline std::vector<Leaf> leaves(const graph::SceneGraph& g) {
    std::vector<Leaf> out;
    collect(g, g.root, glm::dmat4(1.0), nullptr, out);
    return out;
}

inline std::vector<Leaf> leaves_of(const std::string& text) { return leaves(run(text).graph); }

// The shape of the tree as text: "U(D(sphere,T(cube)))" (U union, I
// intersection, D difference, T transform, A appearance).
inline std::string shape(const graph::SceneGraph& g, std::uint32_t id) {
    const graph::Node& n = g.nodes.at(id);
    static const char* prims[] = {"sphere", "box", "cylinder", "torus", "plane", "paraboloid", "hyperboloid", "mesh"};
    if (n.kind == graph::NodeKind::Primitive) return prims[static_cast<int>(n.prim)];
    static const char* kinds[] = {"", "U", "I", "D", "T", "A"};
    std::string s = kinds[static_cast<int>(n.kind)];
    s += '(';
    for (std::uint32_t i = 0; i < n.child_count; ++i) {
        if (i) s += ',';
        s += shape(g, g.child_refs.at(n.first_child + i));
    }
    return s + ')';
}

inline std::string shape_of(const std::string& text) {
    auto g = run(text).graph;
    return shape(g, g.root);
}

}  // namespace kerf::test
