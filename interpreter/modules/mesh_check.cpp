#include "interpreter/modules/mesh_check.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace kerf::eval {

namespace {

std::uint64_t hash_point(const glm::dvec3& p) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (int i = 0; i < 3; ++i) {
        std::uint64_t bits;
        const double v = p[i] == 0 ? 0.0 : p[i];  // -0 and +0 are one position
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 0xBF58476D1CE4E5B9ull;
        h ^= h >> 31;
    }
    return h;
}

bool same_point(const glm::dvec3& a, const glm::dvec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// The vertex id of each point: equal positions share the id of the first.
// Open addressing over point indices (a std::unordered_map of millions of
// points spent most of a large import's check in its node chains).
std::vector<std::uint32_t> weld(const std::vector<glm::dvec3>& points) {
    std::size_t size = 16;
    while (size < 2 * points.size()) size *= 2;
    constexpr std::uint32_t kEmpty = 0xFFFFFFFFu;
    std::vector<std::uint32_t> slot(size, kEmpty);  // a point index per occupied slot
    std::vector<std::uint32_t> id(points.size());
    std::uint32_t next = 0;
    // Slots are hit at random: fetch each one a few points ahead (a table
    // of millions of slots misses the cache on every lookup).
    constexpr std::size_t kAhead = 16;
    std::vector<std::uint64_t> hashes(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) hashes[i] = hash_point(points[i]) & (size - 1);
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        if (i + kAhead < points.size()) __builtin_prefetch(&slot[hashes[i + kAhead]]);
        std::size_t h = hashes[i];
        while (slot[h] != kEmpty && !same_point(points[slot[h]], points[i])) h = (h + 1) & (size - 1);
        if (slot[h] == kEmpty) {
            slot[h] = i;
            id[i] = next++;
        } else {
            id[i] = id[slot[h]];
        }
    }
    return id;
}

struct EdgeUse {
    std::uint64_t key;  // lower vertex << 32 | higher vertex
    std::uint32_t face;
    bool forward;       // the face runs it from lower to higher
};

}  // namespace

MeshCheck check_mesh(graph::PolygonMesh& mesh) {
    MeshCheck out;
    const std::vector<std::uint32_t> vertex = weld(mesh.points);
    // Every edge use, then grouped by edge.
    std::vector<EdgeUse> uses;
    uses.reserve(3 * mesh.faces.size());
    std::vector<bool> valid(mesh.faces.size(), false);
    std::vector<std::uint32_t> c;
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        const auto& face = mesh.faces[f];
        c.clear();
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
    // Links in one array, a contiguous run per face (first[f] .. first[f+1]).
    struct Link {
        std::uint32_t other;
        bool same;
    };
    std::vector<bool> on_bad_edge(mesh.faces.size(), false);  // an edge of one face, or of many
    std::vector<std::uint32_t> first(mesh.faces.size() + 1, 0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // uses[i], uses[i + 1] of two-face edges
    pairs.reserve(uses.size() / 2);
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        while (j < uses.size() && uses[j].key == uses[i].key) ++j;
        const std::size_t n = j - i;
        if (n != 2)
            for (std::size_t k = i; k < j; ++k) on_bad_edge[uses[k].face] = true;
        if (n == 1) ++out.open_edges;
        else if (n > 2) ++out.nonmanifold_edges;
        else if (uses[i].face != uses[i + 1].face) {
            pairs.emplace_back(std::uint32_t(i), std::uint32_t(i + 1));
            ++first[uses[i].face + 1];
            ++first[uses[i + 1].face + 1];
        }
        i = j;
    }
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) first[f + 1] += first[f];
    std::vector<Link> links(first.back());
    {
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (const auto& [i, k] : pairs) {
            const bool same = uses[i].forward == uses[k].forward;
            links[fill[uses[i].face]++] = {uses[k].face, same};
            links[fill[uses[k].face]++] = {uses[i].face, same};
        }
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
            for (std::uint32_t li = first[f]; li < first[f + 1]; ++li) {
                const Link& l = links[li];
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
