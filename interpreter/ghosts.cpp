// The `%` and `#` modifiers' ghosts (csg/ghosts.hpp, docs/openscad.md
// "Modifiers"): recorded where their statements run, under the product of
// the transforms around them (ModuleState::ghost_frames), and gathered at
// the end of the run into one tree per kind beside the solid's.
#include <cmath>
#include <string>

#include "interpreter/evaluator.hpp"

namespace kerf::eval {

namespace {

// What a transform does to 2D shapes: its action in the plane, as the
// transforms themselves keep for flat children (modules/transforms.cpp).
glm::dmat4 planar_part(const glm::dmat4& m) {
    glm::dmat4 p(1.0);
    p[0][0] = m[0][0], p[0][1] = m[0][1];
    p[1][0] = m[1][0], p[1][1] = m[1][1];
    p[3][0] = m[3][0], p[3][1] = m[3][1];
    return p;
}

// Whether the map keeps some volume (area for 2D): |det| against the
// columns' lengths (Hadamard's bound), so the model's size does not matter.
bool keeps_volume(const glm::dmat4& m, bool flat) {
    const glm::dmat3 l(m);
    double det = 0, lengths = 0;
    if (flat) {
        det = l[0][0] * l[1][1] - l[0][1] * l[1][0];
        lengths = glm::length(glm::dvec2(l[0])) * glm::length(glm::dvec2(l[1]));
    } else {
        det = glm::determinant(l);
        lengths = glm::length(l[0]) * glm::length(l[1]) * glm::length(l[2]);
    }
    return std::isfinite(det) && std::abs(det) > 1e-12 * lengths;
}

const char* modifier_name(csg::GhostKind kind) { return kind == csg::GhostKind::Background ? "'%'" : "'#'"; }

}  // namespace

void Evaluator::record_ghost(const ast::Stmt& st, csg::GhostKind kind, std::uint32_t node) {
    const bool flat = out_.graph.nodes[node].flat;
    glm::dmat4 world(1.0);
    for (const ModuleState::GhostFrame& f : modules_.ghost_frames) {
        if (f.hides) {
            warn(st.loc, std::string(modifier_name(kind)) + " inside " + f.hides +
                             "() shows no ghost, as in OpenSCAD's preview" +
                             (kind == csg::GhostKind::Highlight ? " (the part is in the solid)" : ""));
            return;
        }
        world = world * (flat ? planar_part(f.m) : f.m);
    }
    if (!keeps_volume(world, flat)) {
        warn(st.loc, std::string(modifier_name(kind)) + ": the transforms around this part flatten it: no ghost is shown");
        return;
    }
    ModuleState::Ghost g{node, kind, world, csg::kNone, st.loc};
    // A `%` part keeps the colour around it, as OpenSCAD's preview draws it
    // (with that colour's alpha); a `#` part is always the highlight pink.
    if (kind == csg::GhostKind::Background && !modules_.materials.empty()) {
        modules_.ghost_colors.push_back(modules_.materials.back().m);
        g.color = std::uint32_t(modules_.ghost_colors.size() - 1);
    }
    modules_.ghosts.push_back(g);
}

void Evaluator::build_ghost_roots(const SourceLoc& top) {
    const std::vector<ModuleState::Ghost>& ghosts = modules_.ghosts;
    // With `!`, only the ghosts inside the statement that became the root.
    const std::size_t from = root_override_ >= 0 ? root_ghosts_[0] : 0;
    const std::size_t to = root_override_ >= 0 ? root_ghosts_[1] : ghosts.size();
    for (csg::GhostKind kind : {csg::GhostKind::Background, csg::GhostKind::Highlight}) {
        const std::size_t mark = out_.mark();
        for (std::size_t i = from; i < to; ++i) {
            const ModuleState::Ghost& g = ghosts[i];
            if (g.kind != kind) continue;
            const std::size_t at = out_.mark();
            const bool flat = out_.graph.nodes[g.node].flat;
            out_.push(g.node);
            out_.add_matrix(g.world);
            out_.make_node(at, graph::NodeKind::Transform, g.loc, std::uint32_t(out_.graph.matrices.size() - 1));
            // A 2D part is a plate 1 thick on z = 0, as the 2D model is (run()).
            if (flat) out_.extrude(at, -0.5, 0.5, g.loc);
            if (kind == csg::GhostKind::Background) {
                out_.graph.materials.push_back(g.color != csg::kNone ? modules_.ghost_colors[g.color]
                                                                     : csg::ghost_material(kind));
                out_.make_node(at, graph::NodeKind::Appearance, g.loc, std::uint32_t(out_.graph.materials.size() - 1));
            }
        }
        if (out_.mark() == mark) continue;
        out_.graph.ghost_roots[std::size_t(kind)] = out_.make_node(mark, graph::NodeKind::Union, top);
        out_.pending.resize(mark);
    }
}

}  // namespace kerf::eval
