#include "render/adaptive_aa.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "csg/membership.hpp"
#include "render/adaptive.hpp"
#include "render/corner_probes.hpp"
#include "render/edge_coverage.hpp"
#include "render/edge_crossing.hpp"

namespace kerf::render {

namespace {

// The second pass over one render's candidates; the probes are the
// calling thread's (one tile at a time, corner_probes.hpp).
class Refinement {
public:
    Refinement(const PixelSampler& sampler, const CentreSamples& centres, const RenderOptions& options,
               const std::array<int, 4>& region)
        : sampler_(sampler), centres_(centres), region_(region), srgb8_(options.srgb8),
          refine_(options.aa_samples), threshold_(int(std::lround(options.aa_threshold * 255))),
          // A straight edge located to 1/2^steps of a side: 1/16 for the
          // default 16 samples, as fine as their 4 × 4 strata.
          steps_(std::max(1, int(std::ceil(std::log2(double(options.aa_samples)))))),
          precision_(std::ldexp(1.0, -steps_)), generation_(CornerProbes::next_generation()),
          leaf_node_(sampler.scene().leaves.size(), csg::kNone) {
        // A leaf that several nodes share has no one place in the tree:
        // kNone, and cuts_away() says nothing about it (as the tracer's
        // structural rules refuse such leaves, shadow_rays.cpp).
        const csg::Scene& scene = sampler.scene();
        std::vector<std::uint8_t> uses(scene.leaves.size(), 0);
        for (std::uint32_t i = 0; i < scene.nodes.size(); ++i)
            if (scene.nodes[i].op == csg::Op::Leaf) {
                const std::uint32_t leaf = scene.nodes[i].first;
                if (uses[leaf] < 2) ++uses[leaf];
                leaf_node_[leaf] = uses[leaf] == 1 ? i : csg::kNone;
            }
    }

    // The pixels [x0, x1) of row y, one row of a block of a tile (tiles.hpp;
    // `traced` false: a culled block's). Most pixels keep their centre:
    // that test inline, the rest (candidate()) not. A run of pixels whose
    // neighbourhoods all hold one look (CentreSamples::uniform_run) is
    // found once, up to the end of the tile, and its pixels skip the
    // test; the run outlives the call, so that the blocks to its right on
    // the row skip it too (a background row's next blocks, whole). Taken a
    // row at a time, not a pixel: the run's bounds are read once a row.
    // Once a pixel of the block's row lies on no run, its next pixels are
    // not asked for one (holes_40 at 2048²: 934,000 pixels tested one by
    // one, most runs asked for in vain, a rim or a shaded wall every few
    // pixels); a run starts where a block's row does.
    void row(int x0, int x1, int y, ThreadState& ts, bool traced) const {
        Run& run = last_run();
        int x = x0;
        if (y == run.y && run.generation == generation_ && run.from <= x0) x = std::max(x0, std::min(run.to, x1));
        const int limit = std::min(region_[0] + ((x0 - region_[0]) / kTile + 1) * kTile, region_[2]);
        bool runs = true;
        while (x < x1) {
            const int to = runs ? centres_.uniform_run(x, y, limit) : x;
            if (to > x) {
                run = Run{x, to, y, generation_};
                x = to;
                continue;
            }
            runs = false;
            if (const unsigned unlike = centres_.unlike_neighbours(x, y, threshold_)) candidate(x, y, unlike, ts, traced);
            ++x;
        }
    }

private:
    // Pixels [from, to) of row y of the render with `generation` need no test.
    struct Run {
        int from = 0, to = 0, y = 0;
        std::uint64_t generation = 0;
    };
    // The calling thread's last run.
    static Run& last_run() {
        static thread_local Run run;
        return run;
    }
    // Pixel (x, y), whose neighbours in `unlike` (CentreSamples::unlike_neighbours) do not look like it.
    [[gnu::noinline]] void candidate(int x, int y, unsigned unlike, ThreadState& ts, bool traced) const;
    // What a probe looks like to the first pass: the ground as a miss.
    bool alike(const CornerProbe& a, const CornerProbe& b) const { return CentreSamples::alike(a.look, b.look, threshold_); }
    bool like_centre(int x, int y, const CornerProbe& p) const { return centres_.looks_alike(x, y, p.look, threshold_); }
    // A sample through (px, py) with what the first pass compares: its
    // look, surface and whether it saw the ground.
    CornerProbe probe_at(double px, double py, ThreadState& ts, bool traced) const {
        CornerProbe p;
        ts.on_ground = false;
        ts.hit.t = -1;
        p.color = sampler_.sample(px, py, ts, traced, &p.surface);
        p.on_ground = ts.on_ground;
        p.hit = ts.hit;
        p.look = centres_.look(p.on_ground ? sampler_.miss() : p.color, p.surface);  // found once, compared often
        return p;
    }
    CornerProbe& corner(int cx, int cy, ThreadState& ts, bool traced) const;
    glm::dvec3 centre_color(int x, int y, ThreadState& ts, bool traced) const;
    std::optional<glm::dvec3> gradient(int x, int y, const std::array<const CornerProbe*, 4>& k, ThreadState& ts,
                                       bool traced) const;
    int like(double px, double py, const CornerProbe& p, const CornerProbe& q, ThreadState& ts, bool traced,
             std::optional<glm::dvec3>& color) const;
    // Which of p and q pixel (x, y)'s centre looks like, as like() asks of a sample.
    int centre_like(int x, int y, const CornerProbe& p, const CornerProbe& q) const {
        if (p.surface != q.surface) {
            const std::uint32_t seen = centres_.surface(x, y);
            return seen == p.surface ? 0 : seen == q.surface ? 1 : -1;
        }
        const bool like_p = like_centre(x, y, p), like_q = like_centre(x, y, q);
        return like_p == like_q ? -1 : like_q;
    }
    const SideProbe& side(int cx, int cy, bool vertical, ThreadState& ts, bool traced) const;
    struct Prediction {
        double at = 0;
        // Which of the two confirming samples is enough: 0 both; 1 only
        // the one past the prediction (towards q), -1 only the one before.
        int confirm = 0;
    };
    std::optional<Prediction> predicted(int cx, int cy, bool vertical, const CornerProbe& p,
                                        const CornerProbe& q) const;
    std::optional<double> outline(int cx, int cy, bool vertical, const CornerProbe& p, const CornerProbe& q) const;
    // The tangent plane at corner (cx, cy)'s hit (`p`, which hit the solid).
    const TangentPlane& plane(double cx, double cy, const CornerProbe& p) const {
        if (!p.has_plane) {
            glm::dvec3 o, d;
            sampler_.ray(cx, cy, o, d);
            const glm::dvec3 at = o + p.hit.t * d;
            p.plane = TangentPlane{at, sampler_.normal(p.hit, at)};
            p.has_plane = true;
        }
        return p.plane;
    }
    // The signed distance from world point w to the leaf whose surface `hit` is on.
    double leaf_distance(const TraceHit& hit, const glm::dvec3& w) const {
        const csg::Leaf& leaf = sampler_.scene().leaves[hit.surface.leaf];
        return csg::surface_distance(leaf, leaf.object_from_world.point(w));
    }
    bool cuts_away(std::uint32_t g, std::uint32_t f) const;
    int face_model(const glm::dvec3& o, const glm::dvec3& d, glm::dvec2 c, const CornerProbe& f,
                   const CornerProbe& g) const;
    bool faces_show(int x, int y, glm::dvec2 at, const std::array<const CornerProbe*, 4>& k, const int (&face)[2],
                    const int (&other)[2], std::uint32_t surface) const;
    std::optional<glm::dvec3> straight_edge(int x, int y, const std::array<const CornerProbe*, 4>& k, ThreadState& ts,
                                            bool traced) const;
    bool by_surface(int x, int y, const std::array<const CornerProbe*, 4>& k, std::array<bool, 4>& a, int& b,
                    bool& centre_a, glm::dvec3 (&sum)[2], int (&count)[2], ThreadState& ts, bool traced) const;

    static CornerProbes& probes() {
        static thread_local CornerProbes p;
        return p;
    }

    const PixelSampler& sampler_;
    const CentreSamples& centres_;
    const std::array<int, 4> region_;
    const bool srgb8_;
    const SamplePattern refine_;
    const int threshold_;
    const int steps_;
    const double precision_;  // 1/2^steps_ of a side
    const std::uint64_t generation_;
    std::vector<std::uint32_t> leaf_node_;  // per leaf, its node (kNone: shared by several)
};

// The corner (cx, cy) of the current tile, traced and shaded once (when a
// pixel first needs it).
CornerProbe& Refinement::corner(int cx, int cy, ThreadState& ts, bool traced) const {
    CornerProbe& p = probes().at(cx, cy);
    if (p.traced) {
        PixelSampler::set_covered(PixelSampler::covered() + (sampler_.alpha() ? p.cover : 0.0));
    } else {
        PixelSampler::set_last_cover(0);  // a culled sample traces nothing and covers nothing
        p = probe_at(cx, cy, ts, traced);
        p.cover = PixelSampler::last_cover();
        p.traced = true;
    }
    return p;
}

// The centre sample's colour. An 8-bit image stores it to 8 bits anyway:
// decoded from its look, not traced again (a mean of 5 moves by at most a
// tenth of a code). Float images trace it again.
glm::dvec3 Refinement::centre_color(int x, int y, ThreadState& ts, bool traced) const {
    const std::optional<glm::dvec3> kept = srgb8_ && !sampler_.alpha() ? centres_.color(x, y) : std::nullopt;
    return kept ? *kept : sampler_.sample(x + 0.5, y + 0.5, ts, traced, nullptr);
}

// Pixel (x, y)'s colour if its look changes smoothly across one surface
// (shading that turns faster than the threshold between pixels), else
// nothing. `k`: its shaded corners in order round it. The middle of each
// quarter of the pixel lies halfway between the centre and that quarter's
// corner: a linear change puts its sample at their mean. All four within
// half the threshold of that, the pixel is the mean of those 9 samples;
// an edge (a shadow's) between the centre and a corner that differs from
// it by more than the threshold puts its sample on either side, more than
// half the threshold off, and the pixel takes the full pattern.
std::optional<glm::dvec3> Refinement::gradient(int x, int y, const std::array<const CornerProbe*, 4>& k,
                                               ThreadState& ts, bool traced) const {
    // Ghosts change a look without a surface: their pixels keep the full pattern.
    const std::uint32_t own = centres_.surface(x, y);
    if (own == 0 || sampler_.ghosts()) return std::nullopt;
    for (const CornerProbe* p : k)
        if (p->surface != own || p->on_ground) return std::nullopt;
    const glm::dvec3 centre = centre_color(x, y, ts, traced);
    glm::dvec3 sum = centre;
    for (int i = 0; i < 4; ++i) {
        // Corner i round the pixel: (0, 0), (1, 0), (1, 1), (0, 1).
        const glm::dvec2 at = glm::dvec2(x, y) + (glm::dvec2(0.5) + pixel_corner(i)) / 2.0;
        const CornerProbe q = probe_at(at.x, at.y, ts, traced);
        if (q.on_ground || !centres_.alike(q.color, q.surface, (centre + k[i]->color) / 2.0, own, threshold_ / 2))
            return std::nullopt;
        sum += q.color + k[i]->color;
    }
    return sum / 9.0;
}

// Which of two probes p and q of different looks a sample through (px, py)
// looks like: 0 (p), 1 (q) or -1 (both or neither: a third surface, a
// gradient). Between two surfaces the surface alone decides, and the
// sample is not shaded (`color` stays empty); between two looks of one
// surface (a shadow's edge) or under ghosts, the look, and `color` gets
// the sample's.
int Refinement::like(double px, double py, const CornerProbe& p, const CornerProbe& q, ThreadState& ts, bool traced,
                     std::optional<glm::dvec3>& color) const {
    if (p.surface != q.surface && !sampler_.ghosts()) {
        const std::uint32_t seen = sampler_.surface(px, py, ts, traced);
        return seen == p.surface ? 0 : seen == q.surface ? 1 : -1;
    }
    const CornerProbe probe = probe_at(px, py, ts, traced);
    const bool like_p = alike(probe, p), like_q = alike(probe, q);
    if (like_p == like_q) return -1;
    color = probe.color;
    return like_q;
}

// Whether csg::intersect_leaf gives a leaf's solid along any line as one
// span with exact ends, so that the crossing is the one end inside the
// side (a mesh, a prism and a lathe have entry points of their own). Not
// a torus: it clips its spans to the window asked, so a span through the
// side's end ends there and every crossing was refused as too near it
// (a quartic solve for nothing); nor a hyperboloid's waist, whose several
// ends leave "the first from p" wrong where q's face is the one asked.
bool analytic(csg::PrimKind kind) {
    using K = csg::PrimKind;
    return kind == K::Sphere || kind == K::Box || kind == K::Cylinder || kind == K::Plane || kind == K::Paraboloid;
}

// A leaf's spans along the line a + u·(b − a), u in [0, 1] (crossing_on_line).
auto spans_on(const csg::Leaf& leaf) {
    return [&leaf](const glm::dvec3& a, const glm::dvec3& b, csg::Span<double>* out) {
        return csg::intersect_leaf<double>(leaf, leaf.object_from_world.point(a), leaf.object_from_world.vector(b - a),
                                           out, 0.0, 1.0);
    };
}

// Where an edge between the surfaces corners p (at (cx, cy)) and q (the
// next one right, or down) see crosses the side between them, predicted
// from their tangent planes (edge_crossing.hpp); nothing where either saw
// no solid.
//
// Exact, and confirmed by one sample (Prediction::confirm), where one
// corner's face meets the other corner's leaf at a point that lies on both
// leaves' surfaces (within 1/256 of the side): the ray through the
// prediction passes through a point of the two surfaces' intersection, the
// edge, whether the face is planar or the side runs along its tangent
// line; and where the other corner's hit lies behind that face's plane, so
// that the face is the nearer one there (a crease, or the face occluding
// what lies behind it, as a hole's rims do). The sample on the other
// corner's side then refuses a prediction whose face goes on beyond it, or
// where a third surface lies; one on the face's own side would not add to
// that. Where the other corner's surface lies in front of the face's plane
// it may hide the face before the prediction (an overhanging top hides the
// line where its leaf meets the floor's plane): both samples.
std::optional<Refinement::Prediction> Refinement::predicted(int cx, int cy, bool vertical, const CornerProbe& p,
                                                            const CornerProbe& q) const {
    if (p.hit.t < 0 || q.hit.t < 0) return std::nullopt;
    glm::dvec3 o0, d0, o1, d1;
    if (!sampler_.ray(cx, cy, o0, d0) || !sampler_.ray(cx + !vertical, cy + vertical, o1, d1)) return std::nullopt;
    const TangentPlane &p_plane = plane(cx, cy, p), &q_plane = plane(cx + !vertical, cy + vertical, q);
    const auto distance = [&](const TraceHit& hit, const glm::dvec3& w) { return leaf_distance(hit, w); };
    // Where `face` (the plane of the corner whose ray is (fo, fd) and hit
    // `own`) meets the other corner's leaf (`other`, ray (go, gd)), and
    // whether that is exact.
    const auto meets = [&](const TangentPlane& face, const TraceHit& own, const TraceHit& other, const glm::dvec3& go,
                           const glm::dvec3& gd, int towards) -> std::optional<Prediction> {
        const auto across = [&](const glm::dvec3& w) { return distance(other, w); };
        // The other leaf's spans along the line a→b (crossing_on_line).
        const csg::Leaf& leaf = sampler_.scene().leaves[other.surface.leaf];
        const LineCrossing line =
            analytic(leaf.kind) ? crossing_on_line(o0, d0, o1, d1, face, spans_on(leaf)) : LineCrossing{};
        const std::optional<double> e = line.applies ? line.at : crossing_on_plane(o0, d0, o1, d1, face, across);
        if (!e) return std::nullopt;
        Prediction r{*e, 0};
        const auto on_face = [&](double s) {
            const glm::dvec3 o = glm::mix(o0, o1, s), d = glm::mix(d0, d1, s);
            return o + glm::dot(face.normal, face.point - o) / glm::dot(face.normal, d) * d;
        };
        // The plane's points on the side's end rays, and its depth on the
        // other corner's ray: crossing_on_line()'s own where it answered
        // (the same numbers: on_face(0) and (1) are its line's ends).
        const double tolerance =
            (line.applies ? glm::distance(line.from, line.to) : glm::distance(on_face(0), on_face(1))) / 256;
        const double behind = !line.applies ? glm::dot(face.normal, face.point - go) / glm::dot(face.normal, gd)
                              : towards > 0 ? line.t1
                                            : line.t0;
        if (std::abs(distance(own, on_face(*e))) <= tolerance && behind > 0 && other.t > behind) r.confirm = towards;
        return r;
    };
    // p's face first, then q's (not copied into a list of tuples: their
    // copies showed in the profile); q's first where only q's is flat (a
    // box's or a plane's: its plane is its surface, and meets the other
    // leaf exactly, while a curved face's plane leaves its surface: a
    // hole's wall beside the plate's top, half the rims' sides).
    const auto flat = [&](const TraceHit& hit) {
        const csg::PrimKind kind = sampler_.scene().leaves[hit.surface.leaf].kind;
        return kind == csg::PrimKind::Box || kind == csg::PrimKind::Plane;
    };
    const bool q_first = flat(q.hit) && !flat(p.hit);
    std::optional<Prediction> from_q;
    if (q_first) {
        from_q = meets(q_plane, q.hit, p.hit, o0, d0, -1);
        if (from_q && from_q->confirm) return from_q;
    }
    const std::optional<Prediction> from_p = meets(p_plane, p.hit, q.hit, o1, d1, 1);
    if (from_p && from_p->confirm) return from_p;
    if (!q_first) {
        from_q = meets(q_plane, q.hit, p.hit, o0, d0, -1);
        if (from_q && from_q->confirm) return from_q;
    }
    if (from_p) return from_p;
    if (from_q) return from_q;
    if (const std::optional<double> e = predicted_crossing(o0, d0, o1, d1, p_plane, q_plane)) return Prediction{*e, 0};
    return std::nullopt;
}

// Where the face that one of the side's corners sees ends along the side,
// the other corner seeing no solid (the outline against the background),
// from the face's own leaf: a box's face is its plane, and the points a
// plane just behind it (as the corner's ray sees it) puts on the side's
// rays lie on one line (crossing_on_line), inside the box at the face's
// corner and leaving it where the face ends, at the box's edge. Nothing
// for another leaf (a curved face's plane leaves its surface), where the
// line does not start inside the leaf (a face of a subtrahend: behind it
// lies the solid, not the leaf), or where the camera's rays share neither
// origin nor direction. docs/quality.md, "The outline from the face's own
// box".
std::optional<double> Refinement::outline(int cx, int cy, bool vertical, const CornerProbe& p,
                                          const CornerProbe& q) const {
    const bool from_p = p.hit.t >= 0;
    const CornerProbe& f = from_p ? p : q;
    const csg::Leaf& leaf = sampler_.scene().leaves[f.hit.surface.leaf];
    if (leaf.kind != csg::PrimKind::Box) return std::nullopt;
    // The face's corner first: the line runs from it to the corner that misses.
    const int fx = from_p ? cx : cx + !vertical, fy = from_p ? cy : cy + vertical;
    const int gx = from_p ? cx + !vertical : cx, gy = from_p ? cy + vertical : cy;
    glm::dvec3 o0, d0, o1, d1;
    if (!sampler_.ray(fx, fy, o0, d0) || !sampler_.ray(gx, gy, o1, d1)) return std::nullopt;
    TangentPlane behind = plane(fx, fy, f);
    // Just behind the face: on it, whether the line lies inside the box is
    // rounding's to say. 1e-9 of the distance moves the crossing by ~1e-5
    // of a pixel at 2048² (a pixel spans ~5e-4 of it).
    const double shift = 1e-9 * glm::distance(behind.point, o0);
    behind.point += (glm::dot(behind.normal, d0) > 0 ? shift : -shift) * behind.normal;
    const LineCrossing line = crossing_on_line(o0, d0, o1, d1, behind, spans_on(leaf));
    if (!line.applies || !line.at || !line.starts_inside) return std::nullopt;
    return from_p ? *line.at : 1 - *line.at;
}

// Where the look changes along the side from corner (cx, cy) to the next
// one right (or down), to 1/2^steps of the side: between two surfaces
// predicted and confirmed by a sample either side of the prediction (one,
// where it is exact: predicted(); answered by the faces' model where that
// says the corner across shows there, docs/quality.md "The confirming
// samples from the faces"); where one corner misses, where the other's box
// face ends (outline()), confirmed by one sample past it; else (or where a
// sample disagrees) bisection.
const SideProbe& Refinement::side(int cx, int cy, bool vertical, ThreadState& ts, bool traced) const {
    SideProbe& s = probes().side(cx, cy, vertical);
    if (s.traced) return s;
    const CornerProbe &p = probes().at(cx, cy), &q = probes().at(cx + !vertical, cy + vertical);
    s = SideProbe{};
    s.traced = s.clean = true;
    s.sum[0] = s.sum[1] = glm::dvec3(0.0);
    double lo = 0, hi = 1;
    // The side's middle is the midpoint of the centres of the two pixels
    // it divides. Where both look like the same one of its corners, a
    // straight edge (one half-plane holds both) leaves the middle on
    // their side: the first step is free.
    const std::array<int, 4> area = centres_.area();
    const int bx = vertical ? cx - 1 : cx, by = vertical ? cy : cy - 1;  // the pixel before the side; (cx, cy) after
    if (!sampler_.ghosts() && bx >= area[0] && by >= area[1] && cx < area[2] && cy < area[3]) {
        const int before = centre_like(bx, by, p, q);
        if (before >= 0 && before == centre_like(cx, cy, p, q)) (before == 0 ? lo : hi) = 0.5;
    }
    const auto step = [&](double m) {
        std::optional<glm::dvec3> color;
        const int seen = like(cx + (vertical ? 0 : m), cy + (vertical ? m : 0), p, q, ts, traced, color);
        if (seen < 0) return s.clean = false;
        (seen == 0 ? lo : hi) = m;
        if (color) s.sum[seen] += *color, ++s.count[seen];
        return true;
    };
    // The confirming sample at m of a prediction exact from p's face
    // (`towards` 1) or q's (-1), answered by the faces' model where it says
    // the corner across shows there (face_model(), as faces_show() answers
    // the sample past a cut-off corner): the face is cut away at m by the
    // leaf the corner across sees. Else (the face shows, or the model says
    // nothing) the sample is traced.
    const auto across = [&](double m, int towards) {
        glm::dvec3 o, d;
        if (!sampler_.ray(cx + (vertical ? 0 : m), cy + (vertical ? m : 0), o, d)) return false;
        const bool from_p = towards > 0;
        const glm::dvec2 c = from_p ? glm::dvec2(cx, cy) : glm::dvec2(cx + !vertical, cy + vertical);
        if (face_model(o, d, c, from_p ? p : q, from_p ? q : p) >= 0) return false;
        (from_p ? hi : lo) = m;
        return true;
    };
    const double precision = precision_;
    // Where one corner misses (the solid's outline), where its box face
    // ends (outline()): one sample past that, towards the miss, which must
    // miss (nothing models what lies behind).
    // Between two surfaces (only the surface decides, unshaded) the
    // prediction's two samples bracket the edge to the precision.
    // Where the prediction is exact (predicted()), one of them: the one
    // towards the corner across from the face it came from.
    if (p.surface != q.surface && !sampler_.ghosts() && (p.hit.t < 0) != (q.hit.t < 0)) {
        if (const std::optional<double> e = outline(cx, cy, vertical, p, q); e && *e > lo && *e < hi) {
            const bool from_p = p.hit.t >= 0;
            const double before = *e - precision / 2, past = *e + precision / 2, m = from_p ? past : before;
            const double l = lo, h = hi;
            if (m > lo && m < hi && step(m) && (from_p ? hi == m : lo == m))
                lo = std::max(l, before), hi = std::min(h, past);
        }
    } else if (p.surface != q.surface && !sampler_.ghosts())
        if (const std::optional<Prediction> e = predicted(cx, cy, vertical, p, q); e && e->at > lo && e->at < hi) {
            const double before = e->at - precision / 2, past = e->at + precision / 2;
            if (e->confirm != 0) {
                const double m = e->confirm > 0 ? past : before;
                const double l = lo, h = hi;
                if (m > lo && m < hi && (across(m, e->confirm) || step(m)) && (e->confirm > 0 ? hi == m : lo == m)) {
                    lo = std::max(l, before), hi = std::min(h, past);
                    s.exact = std::int8_t(e->confirm);
                }
            } else {
                for (const double m : {before, past})
                    if (m > lo && m < hi && !step(m)) break;
            }
        }
    // Bisection: halving a bracket of 1 or 1/2 lands on the precision exactly.
    while (s.clean && hi - lo > precision) step((lo + hi) / 2);
    s.at = (lo + hi) / 2;
    return s;
}

// Pixel (x, y)'s corners `k` (in order round it) in three looks, taken as
// two classes by surface (`a`: of corner 0's; `b`: the first corner of
// the other; `centre_a`: the centre of corner 0's), when there are exactly
// two surfaces, the centre sees one of them and looks like all that
// surface's corners, and the other surface's look changes linearly
// between its corners: where two next to each other round the pixel look
// unlike, the middle of the pixel's side between them looks like their
// mean within half the threshold (as gradient() asks), and its colour
// joins its class's (`sum`, `count`). A shadow's edge between them puts
// that sample on one side of it, more than half the threshold off. (With
// the centre's own surface allowed to change too, if it looked like one
// of its corners, small_shell's and large_shell's error at 384² rose
// 0.33 -> 0.36 % and 0.33 -> 0.36 codes: a centre brighter than both its
// surface's corners, on curved segments smaller than a pixel.) Not under
// ghosts, which change a look without a surface.
bool Refinement::by_surface(int x, int y, const std::array<const CornerProbe*, 4>& k, std::array<bool, 4>& a, int& b,
                            bool& centre_a, glm::dvec3 (&sum)[2], int (&count)[2], ThreadState& ts,
                            bool traced) const {
    if (sampler_.ghosts()) return false;
    b = -1;
    for (int i = 0; i < 4; ++i) {
        a[i] = k[i]->surface == k[0]->surface;
        if (a[i]) continue;
        if (b < 0) b = i;
        else if (k[i]->surface != k[b]->surface) return false;  // a third surface
    }
    if (b < 0) return false;  // one surface: gradient()'s
    const std::uint32_t own = centres_.surface(x, y);
    if (own != k[0]->surface && own != k[b]->surface) return false;
    centre_a = own == k[0]->surface;
    for (int i = 0; i < 4; ++i)
        if (a[i] == centre_a && !like_centre(x, y, *k[i])) return false;
    for (int i = 0; i < 4; ++i) {
        const CornerProbe &p = *k[i], &q = *k[(i + 1) % 4];
        if (a[i] != a[(i + 1) % 4] || alike(p, q)) continue;
        const glm::dvec2 at = glm::dvec2(x, y) + (pixel_corner(i) + pixel_corner((i + 1) % 4)) / 2.0;
        const CornerProbe m = probe_at(at.x, at.y, ts, traced);
        if (m.surface != p.surface || m.on_ground != p.on_ground || p.on_ground != q.on_ground ||
            !centres_.alike(m.color, m.surface, (p.color + q.color) / 2.0, p.surface, threshold_ / 2))
            return false;
        sum[!a[i]] += m.color, ++count[!a[i]];
    }
    return true;
}

// Whether the surfaces' local model says the ray through pixel (x, y)'s
// point `at` sees `surface`, without tracing it: where both sides the edge
// crosses were located by exact predictions (predicted(): face corner
// `face[j]`'s plane meets corner `other[j]`'s leaf on the face's own
// surface, confirmed by a sample) from one surface's face against one
// other leaf. Along each face's plane, the ray through `at` meets the plane
// on the face's own surface (its leaf's distance within 1/256 of the way
// from the face's corner, times the ray's cosine to the plane's normal),
// and the other leaf's distance there, clear of 0 by 1/256 of the way,
// has the sign it has at the face's corner (the face shows
// there) or the other (the other surface does). The corner test's sample
// past the line's middle (straight_edge) asks this: a corner of the solid
// there, or an edge curving past it, puts the point on the other side, or
// off the face; where a face is curved (its plane leaves its surface) or
// the point lies on the edge, nothing is said and the sample is traced.
// What it cannot see, as no model can: a third surface that reaches the
// point but none of the pixel's corners, side samples and centre.
bool Refinement::faces_show(int x, int y, glm::dvec2 at, const std::array<const CornerProbe*, 4>& k,
                            const int (&face)[2], const int (&other)[2], std::uint32_t surface) const {
    if (face[0] < 0 || face[1] < 0) return false;
    const std::uint32_t a = k[face[0]]->surface, b = k[other[0]]->surface;
    if (k[face[1]]->surface != a || k[other[1]]->surface != b || a == b || (surface != a && surface != b))
        return false;
    glm::dvec3 o, d;
    if (!sampler_.ray(x + at.x, y + at.y, o, d)) return false;
    for (int j = 0; j < 2 && (j == 0 || face[1] != face[0]); ++j) {
        const glm::dvec2 c = glm::dvec2(x, y) + pixel_corner(face[j]);
        const int shows = face_model(o, d, c, *k[face[j]], *k[other[j]]);
        if (shows == 0 || (shows > 0 ? a : b) != surface) return false;
    }
    return true;
}

// Whether the inside of leaf g lies outside a difference whose minuend
// holds leaf f: g one of its subtrahends, itself or through unions. Then
// f's surface, inside g, is not the solid's (a hole's cylinder and the
// plate's top). Not so where g is part of a subtrahend, intersected
// with another leaf (a trench as the intersection of two boxes: inside
// the one the top may go on, outside the other).
bool Refinement::cuts_away(std::uint32_t g, std::uint32_t f) const {
    const csg::Scene& scene = sampler_.scene();
    if (leaf_node_[g] == csg::kNone || leaf_node_[f] == csg::kNone) return false;  // shared: no one place
    std::uint32_t n = leaf_node_[g], up = scene.nodes[n].parent;
    while (up != csg::kNone && scene.nodes[up].op == csg::Op::Union) n = up, up = scene.nodes[up].parent;
    if (up == csg::kNone || scene.nodes[up].op != csg::Op::Difference) return false;
    const std::uint32_t minuend = scene.children[scene.nodes[up].first];
    if (n == minuend) return false;
    for (std::uint32_t m = leaf_node_[f]; m != csg::kNone; m = scene.nodes[m].parent)
        if (m == minuend) return true;
    return false;
}

// What the faces' local model (faces_show()) says the ray (o, d) sees,
// from the face of corner `c` (probe `f`, which hit the solid) against the
// leaf that probe `g` hit: 1 f's surface, -1 g's (only where g's leaf
// cuts f's away: cuts_away()), 0 nothing.
int Refinement::face_model(const glm::dvec3& o, const glm::dvec3& d, glm::dvec2 c, const CornerProbe& f,
                           const CornerProbe& g) const {
    const TangentPlane& face_plane = plane(c.x, c.y, f);  // its ray was traced: the camera has it
    const glm::dvec3 &at_f = face_plane.point, &n = face_plane.normal;
    const double along = glm::dot(n, d);
    if (!(std::abs(along) > 0)) return 0;
    const double t = glm::dot(n, at_f - o) / along;
    if (!(t > 0)) return 0;
    const glm::dvec3 w = o + t * d;
    const double tolerance = glm::distance(at_f, w) / 256;
    // The ray meets the face's own surface about |own| / cos from w
    // (cos: between the ray and the plane's normal); held within the
    // tolerance, the other leaf's distance, Lipschitz 1, keeps its sign
    // there too — also on a curved face seen at a grazing angle.
    const double cos = std::abs(along) / (glm::length(n) * glm::length(d));
    // (Each distance asked only once the one before has passed: the
    // second or third is not needed where an earlier test fails.)
    if (!(std::abs(leaf_distance(f.hit, w)) <= tolerance * cos)) return 0;
    const double across = leaf_distance(g.hit, w);
    if (!(std::abs(across) > tolerance)) return 0;
    if (f.across_leaf != g.hit.surface.leaf) f.across = leaf_distance(g.hit, at_f), f.across_leaf = g.hit.surface.leaf;
    const double at_face = f.across;
    if (at_face == 0) return 0;
    if ((across > 0) == (at_face > 0)) return 1;
    return cuts_away(g.hit.surface.leaf, f.hit.surface.leaf) ? -1 : 0;
}

// Pixel (x, y)'s colour if one straight edge crosses it (`k`: its corners
// in order round it), else nothing.
std::optional<glm::dvec3> Refinement::straight_edge(int x, int y, const std::array<const CornerProbe*, 4>& k,
                                                    ThreadState& ts, bool traced) const {
    std::array<bool, 4> a{};  // like corner 0 (class A), else like corner b (class B)
    int b = -1;
    bool third = false;
    for (int i = 0; i < 4; ++i) {
        a[i] = alike(*k[i], *k[0]);
        if (a[i]) continue;
        if (b < 0) b = i;
        else if (!alike(*k[i], *k[b])) third = true;
    }
    // Each class's colour: the mean of its samples (corners, centre, sides).
    glm::dvec3 sum[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};  // class A, class B
    int count[2] = {0, 0};
    bool centre_a;
    if (third) {
        // A third look: two surfaces, one of whose shading turns fast
        // (holes_40's walls, seen edge on beside the hole)? Else a third
        // surface, or an edge within one (a shadow's).
        if (!by_surface(x, y, k, a, b, centre_a, sum, count, ts, traced)) return std::nullopt;
    } else {
        if (b < 0) return std::nullopt;  // the centre differs from all four corners: a thin feature
        centre_a = like_centre(x, y, *k[0]);
        if (centre_a == like_centre(x, y, *k[b])) return std::nullopt;
    }
    int changes = 0;
    for (int i = 0; i < 4; ++i) changes += a[i] != a[(i + 1) % 4];
    if (changes != 2) return std::nullopt;  // two edges, or a corner of the solid
    std::array<glm::dvec2, 4> cross{};
    int crossed[2], n = 0;
    // Per crossed side, the corner whose face's exact prediction located
    // it and the corner across (-1: not located so).
    int face[2] = {-1, -1}, other[2] = {-1, -1};
    for (int i = 0; i < 4; ++i) {
        if (a[i] == a[(i + 1) % 4]) continue;
        // Side i of the pixel runs from corner i to i + 1; the probes run
        // left to right and top to bottom: sides 2 and 3 backwards.
        static constexpr int dx[4] = {0, 1, 0, 0}, dy[4] = {0, 0, 1, 0};
        const SideProbe& s = side(x + dx[i], y + dy[i], i % 2 == 1, ts, traced);
        if (!s.clean) return std::nullopt;
        const bool backwards = i >= 2;
        // The probe's first corner is pixel corner i, or i + 1 when backwards.
        const bool first_a = a[backwards ? (i + 1) % 4 : i];
        sum[!first_a] += s.sum[0], count[!first_a] += s.count[0];
        sum[first_a] += s.sum[1], count[first_a] += s.count[1];
        cross[i] = on_side(i, backwards ? 1 - s.at : s.at);
        if (s.exact != 0) {
            face[n] = (s.exact > 0) != backwards ? i : (i + 1) % 4;
            other[n] = face[n] == i ? (i + 1) % 4 : i;
        }
        crossed[n++] = i;
    }
    // The centre must lie on its own class's side of the line (or within
    // the crossings' precision of it): else the edge bends. (Corner 0 is of
    // class A.)
    const double d = side_distance(cross[crossed[0]], cross[crossed[1]], pixel_corner(0), {0.5, 0.5});
    const double tolerance = precision_;
    if (centre_a ? d < -tolerance : d > tolerance) return std::nullopt;
    // Two adjacent sides cut off the corner between them. A corner of the
    // solid there (two edges meeting inside the pixel) keeps that corner's
    // look on the far side of the line, beyond what the centre shows: one
    // more sample, 2/2^steps past the middle of the line, away from that
    // corner.
    if ((crossed[1] - crossed[0]) % 2 == 1) {
        const int odd = crossed[1] - crossed[0] == 1 ? crossed[1] : 0, rest = (odd + 2) % 4;
        const glm::dvec2 m = (cross[crossed[0]] + cross[crossed[1]]) / 2.0;
        const glm::dvec2 at = m + 2 * tolerance * glm::normalize(m - pixel_corner(odd));
        if (!faces_show(x, y, at, k, face, other, k[rest]->surface)) {
            std::optional<glm::dvec3> color;
            if (like(x + at.x, y + at.y, *k[rest], *k[odd], ts, traced, color) != 0) return std::nullopt;
            if (color) sum[!a[rest]] += *color, ++count[!a[rest]];
        }
    }
    for (int i = 0; i < 4; ++i) sum[!a[i]] += k[i]->color, ++count[!a[i]];
    sum[!centre_a] += centre_color(x, y, ts, traced), ++count[!centre_a];
    const double area = covered_area(a, cross);
    return area * (sum[0] / double(count[0])) + (1 - area) * (sum[1] / double(count[1]));
}

void Refinement::candidate(int x, int y, unsigned unlike, ThreadState& ts, bool traced) const {
    PixelSampler::set_covered(0);
    // Probes at the corners first: a straight edge that crosses the pixel
    // separates its centre from some neighbour's, and then puts a corner
    // next to that neighbour on the neighbour's side (the corner farthest
    // along the line's normal is one of those). So the corners next to the
    // unlike neighbours come first: all like the centre, the pixel lies
    // wholly on the centre's side of what its neighbours saw and keeps its
    // centre. (Candidates whose neighbours differ only by surface once
    // probed their corners' surfaces alone, unshaded, and kept their
    // centre: the error at 384² rose past 16 uniform samples' on the
    // checkered cube, 0.71 -> 0.85 RMSE codes against 0.75, since a
    // pattern's edge on one surface went unseen; docs/quality.md.)
    const unsigned near = corners_next_to(unlike);
    // A corner is shared by up to 4 candidates: traced once per tile
    // (corner_probes.hpp), the same value whichever pixel asks.
    probes().enter(region_[0] + (x - region_[0]) / kTile * kTile, region_[1] + (y - region_[1]) / kTile * kTile,
                   generation_);
    std::array<const CornerProbe*, 4> round{};  // the corners in order round the pixel
    bool same = true;
    const auto probe = [&](unsigned corners) {
        for (int i = 0; i < 4; ++i) {
            if (!(corners >> i & 1)) continue;
            const CornerProbe& p = corner(x + (i & 1), y + (i >> 1), ts, traced);
            round[i < 2 ? i : 5 - i] = &p;
            same = same && like_centre(x, y, p);
        }
    };
    probe(near);
    if (same && near != 15) return;
    probe(~near & 15);
    if (same) {  // unlike neighbours all round (a gradient): the mean of the five
        glm::dvec3 sum(0.0);
        for (const CornerProbe* p : round) sum += p->color;
        sampler_.put(x, y, (centre_color(x, y, ts, traced) + sum) / 5.0, 5);
        return;
    }
    // One straight edge across the pixel: located on the sides it crosses,
    // its share of the pixel exact for that line. Not with --alpha, whose
    // coverage counts samples.
    ts.refining = true;
    const std::optional<glm::dvec3> edge = sampler_.alpha() ? std::nullopt : straight_edge(x, y, round, ts, traced);
    ts.refining = false;
    if (edge) {
        ++ts.edge_pixels;
        sampler_.put(x, y, *edge, 1);
        return;
    }
    if (!sampler_.alpha()) {
        // Its samples shaded as a pixel's one sample, as the corners are.
        const std::optional<glm::dvec3> smooth = gradient(x, y, round, ts, traced);
        if (smooth) {
            sampler_.put(x, y, *smooth, 1);
            return;
        }
    }
    ++ts.refined_pixels;
    PixelSampler::set_covered(0);
    ts.refining = true;
    sampler_.put(x, y, sampler_.mean(refine_, x, y, ts, traced), refine_.count());
    ts.refining = false;
}

}  // namespace

bool render_adaptive(const TilePasses& tiles, const PixelSampler& sampler, const RenderOptions& options,
                     const std::array<int, 4>& region, const std::function<void(double)>& progress) {
    // Band by band (adaptive_aa.hpp): the centres (about a quarter of the
    // time), then the band's refinement, which reads the centres one row
    // either side.
    CentreSamples centres(region, options.width, options.height, kAaBand + 2);
    const Refinement refinement(sampler, centres, options, region);
    const std::array<int, 4> area = centres.area();
    // The look of the miss colour, the most common sample's, found once.
    const std::uint64_t miss_look = centres.look(sampler.miss(), 0);
    // Whether the area has a ring outside the region (a crop): else no
    // pixel of the first pass needs the test for it.
    const bool ring = area != region;
    // The centres' codes go to the image as they are (PixelSampler::put_codes).
    const bool codes_kept = sampler.codes_kept();
    const double rows = region[3] - region[1];
    // A centre's colour c (seeing `surface`, `ground`: ThreadState::on_ground)
    // kept: its look set, the pixel stored when it lies in the region.
    const auto keep = [&](int x, int y, const glm::dvec3& c, std::uint32_t surface, bool ground) {
        const glm::dvec3& seen = ground ? sampler.miss() : c;
        const std::uint64_t look = centres.set_look(
            x, y, seen == sampler.miss() ? miss_look | std::uint64_t(surface) << 32 : centres.look(seen, surface),
            ground);
        if (ring && (x < region[0] || x >= region[2] || y < region[1] || y >= region[3])) {
            PixelSampler::set_covered(0);
        } else if (ground) {
            sampler.put(x, y, c, 1);
        } else {
            sampler.put_codes(x, y, c, std::uint32_t(look & 0xFFFFFF));  // the codes the look found for c: not found again
        }
    };
    // A culled block's row: what keep() does for misses, as a run (no looks
    // found, no comparisons: the bytes of store.fill are the miss look's
    // codes, and --alpha's pixels still go one by one).
    const auto culled = [&](int x0, int x1, int y, ThreadState& ts) {
        ts.rays.primary += std::uint64_t(x1 - x0);
        ts.on_ground = false;
        centres.set_looks(x0, x1, y, miss_look);
        PixelSampler::set_covered(0);
        if (ring && (y < region[1] || y >= region[3])) return;
        sampler.put_misses(std::max(x0, region[0]), std::min(x1, region[2]), y);
    };
    static_assert(kBlock <= PixelSampler::kMaxRow);
    bool complete = true;
    int set_to = area[1];  // the centres are set on the rows above this
    for (int y0 = region[1]; y0 < region[3]; y0 += kAaBand) {
        const int y1 = std::min(y0 + kAaBand, region[3]), next = std::min(y1 + 1, area[3]);
        const double from = (y0 - region[1]) / rows, to = (y1 - region[1]) / rows;
        centres.hold_from(std::max(area[1], y0 - 1), set_to);
        const std::array<int, 4> band{area[0], set_to, area[2], next};
        const auto band_progress = progress_part(progress, from, from + (to - from) / 4);
        if (sampler.plain()) {
            // A block's row of centres traced, then shaded (PixelSampler::centre_row).
            complete &= tiles.run_rows(band, band_progress, [&](int x0, int x1, int y, ThreadState& ts, bool traced) {
                if (!traced) return culled(x0, x1, y, ts);
                glm::dvec3 colour[kBlock];
                std::uint32_t surface[kBlock];
                bool ground[kBlock];
                sampler.centre_row(x0, x1, y, ts, colour, surface, ground);
                if (ring || !codes_kept) {
                    for (int i = 0; i < x1 - x0; ++i) {
                        PixelSampler::set_covered(0);
                        keep(x0 + i, y, colour[i], surface[i], ground[i]);
                    }
                    return;
                }
                // keep() for a whole image stored as codes: the row's looks
                // and codes in place (no index per pixel, no crop or coverage
                // to ask about). A look by keep()'s own rule (the miss
                // colour keeps its surface in the high bits); the ground's
                // pixels go through keep().
                std::uint64_t* looks = centres.row(x0, y);
                std::uint32_t rgb[kBlock];
                for (int i = 0; i < x1 - x0; ++i) {
                    if (ground[i]) {
                        keep(x0 + i, y, colour[i], surface[i], true);
                        continue;
                    }
                    const std::uint64_t look = colour[i] == sampler.miss()
                                                   ? miss_look | std::uint64_t(surface[i]) << 32
                                                   : centres.look(colour[i], surface[i]);
                    looks[i] = look;
                    rgb[i] = std::uint32_t(look & 0xFFFFFF);
                }
                sampler.put_codes_row(x0, y, x1 - x0, rgb, ground);
            });
        } else {
            complete &= tiles.run(band, band_progress,
                                  [&](int x, int y, ThreadState& ts, bool traced) {
                                      std::uint32_t surface;
                                      ts.on_ground = false;
                                      // --alpha's count starts at 0 here, not at what the thread's
                                      // last candidate left (one that keeps its centre stores
                                      // nothing, and which thread ran it varies: the coverage did,
                                      // run to run).
                                      PixelSampler::set_covered(0);
                                      const glm::dvec3 c = sampler.sample(x + 0.5, y + 0.5, ts, traced, &surface);
                                      keep(x, y, c, surface, ts.on_ground);
                                  },
                                  culled);
        }
        set_to = next;
        // Only candidates are written again; the rest keep their centre.
        complete &= tiles.run_rows({region[0], y0, region[2], y1}, progress_part(progress, from + (to - from) / 4, to),
                                   [&](int x0, int x1, int y, ThreadState& ts, bool traced) {
                                       refinement.row(x0, x1, y, ts, traced);
                                   },
                                   // Not culled again: the first pass asked already, and the
                                   // candidates' rays in culled blocks are few and cheap (they
                                   // miss the solid's box).
                                   false);
    }
    return complete;
}

}  // namespace kerf::render
