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
            chains.push_back(arc_points(d.cx, d.cy, d.radius, a1, a2, false));
        });
    }
    void addCircle(const DL_CircleData& d) override {
        draw([this, d] {
            if (!radius_ok(d.radius)) return;
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
            if (poly_) current_.push_back(map(d.x, d.y));
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
        if (poly_closed_ && current_.size() >= 3) loops.push_back(std::move(current_));
        else if (current_.size() >= 2) {
            if (poly_closed_) current_.push_back(current_.front());
            for (std::size_t i = 0; i + 1 < current_.size(); ++i) chains.push_back({current_[i], current_[i + 1]});
        }
        current_.clear();
    }

private:
    const DxfOptions& o_;
    std::unordered_map<std::string, std::vector<std::function<void()>>> blocks_;
    std::vector<std::function<void()>>* block_ = nullptr;  // the block being read
    Map2 map_{1.0};                                        // block -> model space while inserting
    int depth_ = 0;
    bool poly_ = false, poly_closed_ = false;
    Chain current_;
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
std::vector<Chain> join_chains(std::vector<Chain> chains, std::size_t& open) {
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
    out.loops = join_chains(std::move(got.chains), out.open_paths);
    for (Chain& l : got.loops) out.loops.push_back(std::move(l));
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
