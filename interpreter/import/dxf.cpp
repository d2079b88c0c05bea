// DXF outlines (dxf.hpp): dxflib reports the entities; this file keeps the
// ones OpenSCAD 2021.01 reads, flattens arcs, joins loose segments into
// loops and picks out the whole circles that can stay exact.
#include "interpreter/import/dxf.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <unordered_map>

// dxflib's headers copy a class whose copy is deprecated (its own warning).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-copy"
#include <dl_creationadapter.h>
#include <dl_dxf.h>
#pragma GCC diagnostic pop

#include "interpreter/import/mesh_import.hpp"
#include "interpreter/modules/plane_map.hpp"

namespace kerf::eval {

namespace {

// OpenSCAD merges segment ends closer than its coarse grid (0.001 drawing
// units after origin and scale); the same rule here, so the same files close.
constexpr double kJoin = 1e-3;

using Chain = std::vector<glm::dvec2>;

// The arc of a polyline vertex's bulge b from p to q: b = tan(θ/4) of its
// included angle θ, counter-clockwise when b > 0, so the arc lies right of
// p→q then; the sagitta is |b|·|q − p|/2.
DxfSegment bulge_arc(glm::dvec2 p, glm::dvec2 q, double b) {
    const glm::dvec2 d = q - p;
    const double len = glm::length(d);
    DxfSegment s;
    s.p = p, s.q = q;
    s.normal = (b > 0 ? 1.0 : -1.0) * glm::dvec2(d.y, -d.x) / len;
    s.sagitta = std::abs(b) * len / 2;
    s.r = (len * len / 4 + s.sagitta * s.sagitta) / (2 * s.sagitta);
    s.centre = (p + q) / 2.0 + s.normal * (s.sagitta - s.r);
    s.hole = false;
    return s;
}

// The points strictly between p and q of the bulge's arc, chords within
// the tolerance of the radius.
Chain bulge_points(glm::dvec2 p, glm::dvec2 q, double b, double tolerance) {
    if (p == q) return {};
    const DxfSegment s = bulge_arc(p, q, b);
    const double sweep = 4 * std::atan(b);  // signed
    const int n = std::max(1, int(std::ceil(circle_segments(tolerance) * std::abs(sweep) / (2 * std::numbers::pi))));
    const double a0 = std::atan2(p.y - s.centre.y, p.x - s.centre.x);
    Chain c;
    for (int i = 1; i < n; ++i) {
        const double t = a0 + sweep * i / n;
        c.push_back(s.centre + s.r * glm::dvec2(std::cos(t), std::sin(t)));
    }
    return c;
}

// Model-space entities are drawn as they come; a BLOCK's are recorded and
// drawn at each INSERT of it, under the insert's map (OpenSCAD reads
// blocks so too: example013.dxf is four inserts of two blocks).
class Collector : public DL_CreationAdapter {
public:
    explicit Collector(const DxfOptions& o) : o_(o) {}

    std::vector<Chain> chains;  // open pieces, to be joined
    std::vector<Chain> loops;   // closed polylines, and circles the insert map does not keep round
    std::vector<DxfCircle> circles;
    std::string bad;            // the first problem seen
    std::size_t curves = 0;     // arcs and circles drawn

    void addBlock(const DL_BlockData& d) override {
        finish();
        block_ = &blocks_[d.name];
        block_->clear();
    }
    void endBlock() override { finish(), block_ = nullptr; }
    void addLine(const DL_LineData& d) override {
        draw([this, d] { chains.push_back({map(d.x1, d.y1), map(d.x2, d.y2)}); });
    }
    void addArc(const DL_ArcData& d) override {
        draw([this, d] {
            if (!radius_ok(d.radius) || !std::isfinite(d.angle1) || !std::isfinite(d.angle2)) return;
            double a1 = d.angle1, a2 = d.angle2;
            while (a2 < a1) a2 += 360;  // counter-clockwise from angle1 to angle2, OpenSCAD's reading
            ++curves;
            chains.push_back(arc_points(d.cx, d.cy, d.radius, a1, a2, false));
        });
    }
    void addCircle(const DL_CircleData& d) override {
        draw([this, d] {
            if (!radius_ok(d.radius)) return;
            ++curves;
            const glm::dvec2 c = map(d.cx, d.cy);
            const glm::dvec2 u = map(d.cx + d.radius, d.cy) - c, v = map(d.cx, d.cy + d.radius) - c;
            const double r = glm::length(u);
            if (std::abs(glm::length(v) - r) <= 1e-12 * r && std::abs(glm::dot(u, v)) <= 1e-12 * r * r)
                circles.push_back({c, r});
            else  // an ellipse under a non-uniform insert scale
                loops.push_back(arc_points(d.cx, d.cy, d.radius, 0, 360, true));
        });
    }
    void addPolyline(const DL_PolylineData& d) override {
        draw([this, closed = bool(d.flags & 1)] { poly_ = true, poly_closed_ = closed; });
    }
    void addVertex(const DL_VertexData& d) override {
        record([this, d] {
            if (poly_) current_.push_back({d.x, d.y, std::isfinite(d.bulge) ? d.bulge : 0.0});
        });
    }
    void endSequence() override { record([this] { finish(); }); }
    void addInsert(const DL_InsertData& d) override {
        draw([this, d] {
            auto it = blocks_.find(d.name);
            if (it == blocks_.end() || depth_ >= 16) return;  // an unknown block, or blocks inserting each other
            if (!std::isfinite(d.ipx + d.ipy + d.sx + d.sy + d.angle)) {
                if (bad.empty()) bad = "a non-finite INSERT";
                return;
            }
            const double t = d.angle * std::numbers::pi / 180;
            Map2 m(1.0);
            m[0] = {d.sx * std::cos(t), d.sx * std::sin(t), 0};
            m[1] = {-d.sy * std::sin(t), d.sy * std::cos(t), 0};
            m[2] = {d.ipx, d.ipy, 1};
            const Map2 outer = map_;
            map_ = outer * m, ++depth_;
            for (const auto& draw_it : it->second) draw_it();
            finish();
            map_ = outer, --depth_;
        });
    }

    // The polyline being read, if any, ended.
    void finish() {
        if (block_) return block_->push_back([this] { finish(); });
        if (!poly_) return;
        poly_ = false;
        const std::size_t n = current_.size();
        bool bulged = false;
        for (std::size_t i = 0; i < n; ++i) bulged |= (poly_closed_ || i + 1 < n) && current_[i].z != 0;
        // A closed polyline with bulges keeps them exact (as chord edges
        // and arcs) when the insert map keeps circles round; otherwise the
        // arcs are flattened here, in block coordinates, then mapped.
        const Map2& a = map_;
        const glm::dvec2 u(a[0]), v(a[1]);
        const bool similar = std::abs(glm::length(u) - glm::length(v)) <= 1e-12 * glm::length(u) &&
                             std::abs(glm::dot(u, v)) <= 1e-12 * glm::dot(u, u);
        if (poly_closed_ && n >= 2 && bulged && similar) {
            Chain loop;
            for (std::size_t i = 0; i < n; ++i) {
                loop.push_back(map(current_[i].x, current_[i].y));
                // A mirror turns a counter-clockwise arc clockwise.
                if (current_[i].z != 0) arcs.push_back({loops.size(), i, determinant(a) < 0 ? -current_[i].z : current_[i].z});
            }
            loops.push_back(std::move(loop));
        } else {
            Chain pts;
            for (std::size_t i = 0; i < n; ++i) {
                const glm::dvec3 p = current_[i], q = current_[(i + 1) % n];
                pts.push_back(map(p.x, p.y));
                if (p.z != 0 && (poly_closed_ || i + 1 < n))
                    for (glm::dvec2 b : bulge_points(glm::dvec2(p), glm::dvec2(q), p.z, o_.tolerance)) pts.push_back(map(b.x, b.y));
            }
            if (poly_closed_ && pts.size() >= 3) loops.push_back(std::move(pts));
            else if (pts.size() >= 2) {
                if (poly_closed_) pts.push_back(pts.front());
                for (std::size_t i = 0; i + 1 < pts.size(); ++i) chains.push_back({pts[i], pts[i + 1]});
            }
        }
        current_.clear();
    }

    struct Arc {
        std::size_t loop, edge;  // loops[loop], from vertex edge to the next
        double bulge;            // tan(included angle / 4), counter-clockwise when positive
    };
    std::vector<Arc> arcs;

private:
    const DxfOptions& o_;
    std::unordered_map<std::string, std::vector<std::function<void()>>> blocks_;
    std::vector<std::function<void()>>* block_ = nullptr;  // the block being read
    Map2 map_{1.0};                                        // block -> model space while inserting
    int depth_ = 0;
    bool poly_ = false, poly_closed_ = false;
    std::vector<glm::dvec3> current_;  // the polyline's vertices, block coordinates, z the bulge
    std::uint64_t entities_ = 0;

    // An entity of the chosen layer: drawn now, or recorded in its block.
    void draw(std::function<void()> f) {
        finish();
        if (!o_.layer.empty() && getAttributes().getLayer() != o_.layer) return;
        record([this, f = std::move(f)] {
            if (++entities_ > o_.max_entities && o_.max_entities && bad.empty())
                bad = "more than " + std::to_string(o_.max_entities) + " entities";
            if (bad.empty()) f();
        });
    }
    void record(std::function<void()> f) {
        if (block_) block_->push_back(std::move(f));
        else f();
    }
    bool radius_ok(double r) {
        if (std::isfinite(r) && r > 0) return true;
        if (bad.empty()) bad = "an arc or circle of radius " + std::to_string(r);
        return false;
    }
    // The arc from a1 to a2 degrees, chords within the tolerance (of the
    // radius), mapped; `closed` leaves out the end that repeats the start.
    Chain arc_points(double cx, double cy, double r, double a1, double a2, bool closed) {
        const int n = std::max(1, int(std::ceil(circle_segments(o_.tolerance) * (a2 - a1) / 360)));
        Chain c;
        for (int i = 0; i < n + !closed; ++i) {
            const double t = (a1 + (a2 - a1) * i / n) * std::numbers::pi / 180;
            c.push_back(map(cx + r * std::cos(t), cy + r * std::sin(t)));
        }
        return c;
    }
    glm::dvec2 map(double x, double y) {
        if (!std::isfinite(x) || !std::isfinite(y)) {
            if (bad.empty()) bad = "a non-finite coordinate";
            return glm::dvec2(0);
        }
        return (apply(map_, glm::dvec2(x, y)) - o_.origin) * o_.scale;
    }
};

// Joins chains end to end: ends within kJoin are one point (hashed on a
// kJoin grid, neighbours searched). Returns the loops; a chain that does
// not close is closed by a straight edge, as OpenSCAD 2021 does ("we don't
// support open paths; closing them to be compatible"), and counted.
std::vector<Chain> join_chains(std::vector<Chain> chains, std::size_t& open, std::vector<Chain>& lone) {
    struct Key {
        std::int64_t x, y;
        bool operator==(const Key&) const = default;
    };
    struct Hash {
        std::size_t operator()(const Key& k) const { return std::hash<std::int64_t>()(k.x * 73856093 ^ k.y); }
    };
    std::vector<glm::dvec2> reps;
    std::unordered_map<Key, std::vector<std::uint32_t>, Hash> cells;
    auto point_id = [&](glm::dvec2 p) {
        const Key k{std::int64_t(std::floor(p.x / kJoin)), std::int64_t(std::floor(p.y / kJoin))};
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                if (auto it = cells.find({k.x + dx, k.y + dy}); it != cells.end())
                    for (std::uint32_t id : it->second)
                        if (glm::length(reps[id] - p) < kJoin) return id;
        reps.push_back(p);
        cells[k].push_back(std::uint32_t(reps.size() - 1));
        return std::uint32_t(reps.size() - 1);
    };
    std::vector<std::uint32_t> head(chains.size()), tail(chains.size());
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> at;  // point -> chains ending there
    for (std::uint32_t i = 0; i < chains.size(); ++i) {
        head[i] = point_id(chains[i].front()), tail[i] = point_id(chains[i].back());
        if (head[i] == tail[i] && chains[i].size() <= 2) continue;  // a zero-length line
        at[head[i]].push_back(i), at[tail[i]].push_back(i);
    }
    std::vector<bool> used(chains.size());
    // The next unused chain at point `p`, turned to start there and used up.
    auto take = [&](std::uint32_t p, std::uint32_t& other_end) -> const Chain* {
        for (std::uint32_t j : at[p])
            if (!used[j]) {
                used[j] = true;
                if (head[j] != p) std::reverse(chains[j].begin(), chains[j].end()), std::swap(head[j], tail[j]);
                other_end = tail[j];
                return &chains[j];
            }
        return nullptr;
    };
    std::vector<Chain> loops;
    for (std::uint32_t i = 0; i < chains.size(); ++i) {
        if (used[i] || (head[i] == tail[i] && chains[i].size() <= 2)) continue;
        used[i] = true;
        Chain loop = chains[i];
        std::uint32_t start = head[i], end = tail[i];
        while (end != start)
            if (const Chain* piece = take(end, end)) loop.insert(loop.end(), piece->begin() + 1, piece->end());
            else break;
        if (end == start) {
            loop.pop_back();  // the start again
        } else {
            // Open: the whole chain, also what leads into its first piece,
            // closed by the straight edge from its end back to its start.
            ++open;
            while (const Chain* piece = take(start, start)) loop.insert(loop.begin(), piece->rbegin(), piece->rend() - 1);
            if (loop.size() == 2) lone.push_back(loop);
        }
        if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
}

bool inside(const Chain& loop, glm::dvec2 p) {  // even-odd
    bool in = false;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const glm::dvec2 a = loop[i], b = loop[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
    }
    return in;
}

bool crosses(const Chain& loop, const DxfCircle& c) {
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const glm::dvec2 a = loop[j] - c.centre, b = loop[i] - c.centre, d = b - a;
        const double t = glm::dot(d, d) > 0 ? std::clamp(-glm::dot(a, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
        const double near = glm::length(a + t * d), far = std::max(glm::length(a), glm::length(b));
        if (near <= c.r + kJoin && far >= c.r - kJoin) return true;
    }
    return false;
}

// The most of u·x over the segment: at an end of the chord, or where the
// circle's normal is u if that point is on the arc.
double support(const DxfSegment& s, glm::dvec2 u) {
    double m = std::max(glm::dot(u, s.p), glm::dot(u, s.q));
    const glm::dvec2 far = s.centre + s.r * u;
    if (glm::dot(s.normal, far - s.p) >= 0) m = std::max(m, glm::dot(u, far));
    return m;
}

// Whether the edge a→b enters the segment's interior: its part beyond the
// chord line comes nearer the centre than the radius.
bool enters(const DxfSegment& s, glm::dvec2 a, glm::dvec2 b) {
    const double eps = 1e-9 * s.r;
    double ha = glm::dot(s.normal, a - s.p), hb = glm::dot(s.normal, b - s.p);
    if (ha <= eps && hb <= eps) return false;
    if (ha < eps) a += (b - a) * ((eps - ha) / (hb - ha)), ha = eps;
    if (hb < eps) b += (a - b) * ((eps - hb) / (ha - hb));
    const glm::dvec2 d = b - a, c = s.centre - a;
    const double t = glm::dot(d, d) > 0 ? std::clamp(glm::dot(c, d) / glm::dot(d, d), 0.0, 1.0) : 0.0;
    return glm::length(a + t * d - s.centre) < s.r - eps;
}

bool overlap(const DxfSegment& s, const DxfSegment& o) {
    const double eps = 1e-9 * std::max(s.r, o.r);
    if (glm::length(s.centre - o.centre) >= s.r + o.r - eps) return false;
    return support(o, s.normal) > glm::dot(s.normal, s.p) + eps && support(s, o.normal) > glm::dot(o.normal, o.p) + eps;
}

// Each bulge of the polylines loops[base..] kept exact when its segment
// meets no other edge, segment or circle; the rest flattened into their
// loops. Then each kept one is a hole where the loops' even-odd fill holds
// it, as a point inside it tells.
template <typename ArcList>
void keep_arcs(DxfShape& out, const ArcList& arcs, std::size_t base, const std::vector<DxfCircle>& circles,
               double tolerance) {
    std::vector<DxfSegment> seg;
    std::vector<bool> keep;
    for (const auto& a : arcs) {
        const Chain& l = out.loops[base + a.loop];
        const glm::dvec2 p = l[a.edge], q = l[(a.edge + 1) % l.size()];
        keep.push_back(p != q);
        seg.push_back(p != q ? bulge_arc(p, q, a.bulge) : DxfSegment{});
    }
    for (std::size_t i = 0; i < seg.size(); ++i) {
        if (!keep[i]) continue;
        const DxfSegment& s = seg[i];
        for (std::size_t li = 0; li < out.loops.size() && keep[i]; ++li) {
            const Chain& l = out.loops[li];
            for (std::size_t e = 0; e < l.size() && keep[i]; ++e)
                if (!(li == base + arcs[i].loop && e == arcs[i].edge) && enters(s, l[e], l[(e + 1) % l.size()]))
                    keep[i] = false;
        }
        for (std::size_t j = 0; j < seg.size() && keep[i]; ++j)
            if (j != i && seg[j].r > 0 && overlap(s, seg[j])) keep[i] = false;
        for (const DxfCircle& c : circles)  // discs apart, so no circle's test needs the arcs
            if (glm::length(c.centre - s.centre) < c.r + s.r + kJoin) keep[i] = false;
    }
    // Flattened arcs, last edge first so the earlier edges keep their indices.
    for (std::size_t k = seg.size(); k-- > 0;) {
        if (keep[k] || seg[k].r == 0) continue;
        Chain& l = out.loops[base + arcs[k].loop];
        const Chain pts = bulge_points(seg[k].p, seg[k].q, arcs[k].bulge, tolerance);
        l.insert(l.begin() + std::ptrdiff_t(arcs[k].edge + 1), pts.begin(), pts.end());
    }
    for (std::size_t i = 0; i < seg.size(); ++i) {
        if (!keep[i]) continue;
        const glm::dvec2 t = (seg[i].p + seg[i].q) / 2.0 + seg[i].normal * (seg[i].sagitta / 2);
        int depth = 0;
        for (const Chain& l : out.loops) depth += inside(l, t);
        seg[i].hole = depth % 2 == 1;
        out.segments.push_back(seg[i]);
    }
}

// dxflib skips what it cannot parse, so a text file that is no DXF at all
// would read as an empty drawing: every other line of an ASCII DXF is an
// integer group code, checked here first to name the line that is not.
void check_group_codes(const std::string& path) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw MeshFormatError("cannot open the file");
    if (size > kMaxImportBytes)
        throw MeshFormatError("longer than 256 MiB (" + std::to_string(size) + " bytes), too large to import");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw MeshFormatError("cannot open the file");
    std::string text;
    for (std::uint64_t n = 1; std::getline(in, text); n += 2) {
        const std::size_t a = text.find_first_not_of(" \t\r"), b = text.find_last_not_of(" \t\r");
        const std::string code = a == std::string::npos ? "" : text.substr(a, b - a + 1);
        char* end = nullptr;
        std::strtol(code.c_str(), &end, 10);
        if (code.empty() || *end != '\0')
            throw MeshFormatError("not a readable DXF file: line " + std::to_string(n) + " is not a group code");
        if (!std::getline(in, text) || text.rfind("EOF", 0) == 0) break;  // what follows EOF is not read
    }
}

}  // namespace

DxfShape import_dxf(const std::string& path, const DxfOptions& options) {
    check_group_codes(path);
    Collector got(options);
    DL_Dxf dxf;
    bool ok = false;
    try {
        ok = dxf.in(path, &got);
    } catch (const std::exception& e) {
        throw MeshFormatError(std::string("not a readable DXF file: ") + e.what());
    }
    got.finish();
    if (!ok) throw MeshFormatError("not a readable DXF file");
    if (!got.bad.empty()) throw MeshFormatError("not a readable DXF file: " + got.bad);
    DxfShape out;
    out.curves = got.curves;
    out.loops = join_chains(std::move(got.chains), out.open_paths, out.lone_lines);
    const std::size_t base = out.loops.size();
    for (Chain& l : got.loops) out.loops.push_back(std::move(l));
    keep_arcs(out, got.arcs, base, got.circles, options.tolerance);
    // A circle stays exact when it meets no other outline and holds none.
    const std::vector<DxfCircle>& cs = got.circles;
    std::vector<bool> exact(cs.size(), true);
    for (std::size_t i = 0; i < cs.size(); ++i) {
        for (const Chain& l : out.loops)
            if (crosses(l, cs[i]) || glm::length(l[0] - cs[i].centre) < cs[i].r) exact[i] = false;
        for (std::size_t j = 0; j < cs.size() && exact[i]; ++j) {
            const double d = glm::length(cs[i].centre - cs[j].centre);
            if (j != i && (d <= cs[i].r + cs[j].r + kJoin) && (d >= std::abs(cs[i].r - cs[j].r) - kJoin || cs[j].r < cs[i].r))
                exact[i] = false;
        }
    }
    for (std::size_t i = 0; i < cs.size(); ++i) {
        if (exact[i]) continue;
        Chain loop;
        circle_chords(cs[i].r, options.tolerance, [&](glm::dvec2 p, glm::dvec2) { loop.push_back(cs[i].centre + p); });
        out.loops.push_back(std::move(loop));
    }
    for (std::size_t i = 0; i < cs.size(); ++i) {
        if (!exact[i]) continue;
        int depth = 0;
        for (const Chain& l : out.loops) depth += inside(l, cs[i].centre);
        out.circles.push_back(cs[i]);
        out.circle_depth.push_back(depth);
    }
    return out;
}

}  // namespace kerf::eval
