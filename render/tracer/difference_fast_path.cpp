// The clearance fast path of a difference with few subtrahends asked for
// its first entry or any span (README.md, "Tracer design"; the distance
// bounds are in clearance.cpp).
#include <algorithm>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

// Minuend span `span` minus only the near subtrahends (`near`, ascending
// indices into `subs`), on [a, b]: `r` pieces from the returned index on;
// scratch from sbase on.
std::uint32_t minus_near(RayState& rs, const std::uint32_t* subs, const std::uint32_t* near, std::uint32_t nnear,
                         std::uint32_t span, std::uint32_t sbase, double a, double b, int& r) {
    rs.scratch->stack.resize(sbase);
    for (std::uint32_t j = 0; j < nnear; ++j) rs.spans(subs[near[j]], a, b, Need::All);
    return rs.subtract_gathered(span, 1, sbase, r);
}

}  // namespace

// The fast path of First/Any for a difference with few subtrahends. A point
// of minuend span i (its entry; for Any, the middle of its part inside the
// window) that is farther than twice the degenerate rule's reach from every
// subtrahend is in the difference, and gathering spans would give the same
// answer. For First, when only a few (kMaxNear) subtrahends are near the entry (a
// ray into a groove), only those are intersected; the piece they leave
// starts at e, and e is the answer if it is clear of all the others.
// Minuend spans are at base.., scratch from sbase on (see FastPath).
FastPath RayState::first_piece_if_clear(const csg::Node& n, std::uint32_t base, std::uint32_t sbase, std::uint32_t i,
                                         double a, double b, Need need) {
    SpanStack& st = scratch->stack;
    Span piece = *st.at(base + i);
    double probe;
    if (const FastPath p = fast_path_probe(piece.t0, piece.t1, a, b, need, eps, probe); p != FastPath::Found) return p;
    const double margin = 2 * eps * len;
    const std::uint32_t* subs = &impl->scene.children[n.first + 1];
    const std::uint32_t nsub = n.count - 1;
    std::uint32_t near[kMaxNear], nnear;
    if (!near_subtrahends(subs, nsub, o + probe * d, margin, near, nnear)) return FastPath::Unknown;
    if (nnear > 0 && need != Need::First) return any_piece_if_clear(n, base, sbase, i, a, b, near, nnear);
    if (nnear > 0) {
        // Span i minus the near subtrahends, on the span's part in the window.
        int r;
        const std::uint32_t rbase = minus_near(*this, subs, near, nnear, base + i, sbase, probe, std::min(b, piece.t1), r);
        int k = 0;
        while (k < r && !(st.at(rbase + std::uint32_t(k))->t0 > a)) ++k;
        // More subtrahends only shrink the pieces: none here, none at all.
        if (k == r || st.at(rbase + std::uint32_t(k))->t0 > b) return k == r ? FastPath::None : FastPath::Past;
        piece = *st.at(rbase + std::uint32_t(k));
        if (!clear_of_all_but(subs, nsub, near, nnear, o + piece.t0 * d, margin)) return FastPath::Unknown;
    }
    *st.at(base) = piece;
    st.resize(base + 1);
    return FastPath::Found;
}

// Any (a shadow ray), with a few (kMaxNear) subtrahends near the probe (a ray
// leaving a groove): span i minus only those, on the window; a piece that
// overlaps the window by more than 2·eps and whose middle is clear of all
// the other subtrahends answers (the sliver of eps round it survives them
// all, as in first_piece_if_clear); no piece overlapping it by more than
// eps: none can (more subtrahends only shrink the pieces); else not proven.
FastPath RayState::any_piece_if_clear(const csg::Node& n, std::uint32_t base, std::uint32_t sbase, std::uint32_t i,
                                      double a, double b, const std::uint32_t* near, std::uint32_t nnear) {
    SpanStack& st = scratch->stack;
    const double p0 = std::max(a, st.at(base + i)->t0), p1 = std::min(b, st.at(base + i)->t1);
    const double margin = 2 * eps * len;
    const std::uint32_t* subs = &impl->scene.children[n.first + 1];
    const std::uint32_t nsub = n.count - 1;
    int r;
    const std::uint32_t rbase = minus_near(*this, subs, near, nnear, base + i, sbase, p0, p1, r);
    bool unsure = false;
    for (int k = 0; k < r; ++k) {
        const Span& piece = *st.at(rbase + std::uint32_t(k));
        const double q0 = std::max(a, piece.t0), q1 = std::min(b, piece.t1);
        if (!(q1 - q0 > eps)) continue;
        if (!probe_fits(q0, q1, eps)) {
            unsure = true;
            continue;
        }
        const double probe = 0.5 * (q0 + q1);
        if (!clear_of_all_but(subs, nsub, near, nnear, o + probe * d, margin)) return FastPath::Unknown;
        Span sliver = piece;
        sliver.t0 = probe - eps;
        sliver.t1 = probe + eps;
        *st.at(base) = sliver;
        st.resize(base + 1);
        return FastPath::Found;
    }
    return unsure ? FastPath::Unknown : FastPath::None;
}

}  // namespace kerf::render
