// The first entry of a difference with many subtrahends (its own BVH), found
// without gathering every subtrahend along the minuend's chord: "which
// subtrahends cover the point c?", growing the window only while c stays
// covered. A ray through a slab with N holes so costs about log N, not N
// (README.md, "Tracer design"; bench/render_models holesN).
#include <algorithm>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

// Minuend span i lies at base + i (spans after base + count are scratch).
// Returns 1 with the entry written at base, 0 if this minuend span has no
// entry, 2 if the search passed the window's end.
//
// Spans gathered on a window are only true inside it (a composite
// subtrahend's far end may still be uncut), so only crossings strictly
// inside the current window [c, end] are trusted. The window starts as the
// point c (most rays: "is the minuend's entry covered?"), then grows to the
// covering spans' claimed exit, then doubles, until it decides.
std::uint32_t RayState::first_entry_by_points(const Accel& subtrahends, std::uint32_t base, std::uint32_t i,
                                               double b) {
    SpanStack& st = scratch->stack;
    const std::uint32_t sbase = st.size();
    const Span rest = *st.at(base + i);
    const double c = rest.t0;
    const double stop = std::min(b, rest.t1) + 2 * eps;  // nothing past this matters
    double end = c + 2 * eps;
    for (;;) {
        st.resize(sbase);
        collect(subtrahends, c - 2 * eps, end);
        int r = 0;
        const std::uint32_t rbase = subtract_gathered(base + i, 1, sbase, r);
        double claimed = end;  // where the gathered spans say coverage from c ends
        for (std::uint32_t k = sbase; k < rbase; ++k) claimed = std::max(claimed, st.at(k)->t1);
        if (r > 0 && (st.at(rbase)->t0 == c || st.at(rbase)->t0 < end - eps)) {
            const Span piece = *st.at(rbase);
            st.resize(sbase);
            if (piece.t0 > b) return 2;
            *st.at(base) = piece;
            st.resize(base + 1);
            return 1;
        }
        if (end >= stop) {  // the window covered everything that matters: no entry
            st.resize(sbase);
            return rest.t1 + 2 * eps > stop ? 2 : 0;
        }
        end = std::min(stop, std::max(claimed + 2 * eps, c + 2 * (end - c)));
    }
}

}  // namespace kerf::render
