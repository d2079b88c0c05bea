#include "interpreter/modules/mesh_check.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace kerf::eval {

namespace {

struct PointHash {
    std::size_t operator()(const glm::dvec3& p) const {
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (int i = 0; i < 3; ++i) {
            std::uint64_t bits;
            const double v = p[i] == 0 ? 0.0 : p[i];  // -0 and +0 are one position
            std::memcpy(&bits, &v, sizeof bits);
            h = (h ^ bits) * 0xBF58476D1CE4E5B9ull;
            h ^= h >> 31;
        }
        return std::size_t(h);
    }
};

struct EdgeUse {
    std::uint64_t key;  // lower vertex << 32 | higher vertex
    std::uint32_t face;
    bool forward;       // the face runs it from lower to higher
};

}  // namespace

MeshCheck check_mesh(graph::PolygonMesh& mesh) {
    MeshCheck out;
    // Vertices by position.
    std::vector<std::uint32_t> vertex(mesh.points.size());
    {
        std::unordered_map<glm::dvec3, std::uint32_t, PointHash> ids;
        ids.reserve(mesh.points.size());
        for (std::size_t i = 0; i < mesh.points.size(); ++i) {
            glm::dvec3 p = mesh.points[i];
            for (int k = 0; k < 3; ++k) p[k] = p[k] == 0 ? 0.0 : p[k];
            vertex[i] = ids.emplace(p, std::uint32_t(ids.size())).first->second;
        }
    }
    // Every edge use, then grouped by edge.
    std::vector<EdgeUse> uses;
    std::vector<bool> valid(mesh.faces.size(), false);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        std::vector<std::uint32_t> c;
        for (std::uint32_t i : face)
            if (i < vertex.size() && (c.empty() || c.back() != vertex[i])) c.push_back(vertex[i]);
        while (c.size() > 1 && c.front() == c.back()) c.pop_back();
        if (c.size() < 3) continue;
        valid[f] = true;
        ++out.faces;
        for (std::size_t k = 0; k < c.size(); ++k) {
            const std::uint32_t a = c[k], b = c[(k + 1) % c.size()];
            if (a == b) continue;
            const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
            uses.push_back(EdgeUse{std::uint64_t(lo) << 32 | hi, std::uint32_t(f), a < b});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });

    // Faces across each two-face edge: (other face, whether the two run it
    // the same way, i.e. disagree).
    struct Link {
        std::uint32_t other;
        bool same;
    };
    std::vector<std::vector<Link>> links(mesh.faces.size());
    std::vector<bool> on_bad_edge(mesh.faces.size(), false);  // an edge of one face, or of many
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        while (j < uses.size() && uses[j].key == uses[i].key) ++j;
        const std::size_t n = j - i;
        if (n != 2)
            for (std::size_t k = i; k < j; ++k) on_bad_edge[uses[k].face] = true;
        if (n == 1) ++out.open_edges;
        else if (n > 2) ++out.nonmanifold_edges;
        else if (uses[i].face != uses[i + 1].face) {
            const bool same = uses[i].forward == uses[i + 1].forward;
            links[uses[i].face].push_back({uses[i + 1].face, same});
            links[uses[i + 1].face].push_back({uses[i].face, same});
        }
        i = j;
    }

    // Consistent orientation per connected part (breadth first), then the
    // sign of each closed part's volume.
    std::vector<std::int8_t> flip(mesh.faces.size(), -1);  // -1: not reached yet
    std::vector<std::uint32_t> queue;
    for (std::uint32_t seed = 0; seed < mesh.faces.size(); ++seed) {
        if (!valid[seed] || flip[seed] >= 0) continue;
        queue.assign(1, seed);
        flip[seed] = 0;
        bool conflict = false;
        for (std::size_t q = 0; q < queue.size(); ++q) {
            const std::uint32_t f = queue[q];
            for (const Link& l : links[f]) {
                const std::int8_t want = std::int8_t(flip[f] ^ (l.same ? 1 : 0));
                if (flip[l.other] < 0) {
                    flip[l.other] = want;
                    queue.push_back(l.other);
                } else if (flip[l.other] != want) {
                    conflict = true;
                }
            }
        }
        // Six times the signed volume of the part as it would be wound, in
        // OpenSCAD's order (clockwise from outside: negative when outward).
        double volume = 0;
        out.nonorientable = out.nonorientable || conflict;
        bool part_closed = !conflict;
        for (std::uint32_t f : queue) {
            part_closed = part_closed && !on_bad_edge[f];
            const auto& face = mesh.faces[f];
            const glm::dvec3& p0 = mesh.points[face[0]];
            double v = 0;
            for (std::size_t k = 1; k + 1 < face.size(); ++k)
                v += glm::dot(p0, glm::cross(mesh.points[face[k]], mesh.points[face[k + 1]]));
            volume += flip[f] ? -v : v;
        }
        // An open part has no inside to point away from: its faces keep
        // their neighbours' orientation only.
        if (part_closed && volume > 0)
            for (std::uint32_t f : queue) flip[f] ^= 1;
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        if (valid[f] && flip[f] == 1) {
            std::reverse(mesh.faces[f].begin(), mesh.faces[f].end());
            ++out.faces_turned;
        }
    return out;
}

}  // namespace kerf::eval
