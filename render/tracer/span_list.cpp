#include "render/tracer/span_list.hpp"

#include <algorithm>

namespace kerf::render {

namespace {

// Seen from outside a difference, a subtrahend's surface is a cut face of the
// minuend: its normal turns round and it shows the minuend's interior.
SpanEnd cut_end(SpanEnd e, std::uint32_t minuend_leaf) {
    e.flip ^= 1;
    e.cut = 1;
    e.mat_leaf = minuend_leaf;
    return e;
}

}  // namespace

int span_union(const Span* a, int na, const Span* b, int nb, Span* out, double eps) {
    int i = 0, j = 0, n = 0;
    while (i < na || j < nb) {
        const Span& s = (j >= nb || (i < na && a[i].t0 <= b[j].t0)) ? a[i++] : b[j++];
        // Touching or overlapping within eps: one span (no internal surface).
        if (n > 0 && s.t0 <= out[n - 1].t1 + eps) {
            if (s.t1 > out[n - 1].t1) {
                out[n - 1].t1 = s.t1;
                out[n - 1].e1 = s.e1;
            }
        } else {
            out[n++] = s;
        }
    }
    return n;
}

int span_intersection(const Span* a, int na, const Span* b, int nb, Span* out, double eps) {
    int i = 0, j = 0, n = 0;
    while (i < na && j < nb) {
        const Span& x = a[i];
        const Span& y = b[j];
        Span r;
        r.inner = x.inner;
        if (x.t0 >= y.t0) { r.t0 = x.t0; r.e0 = x.e0; } else { r.t0 = y.t0; r.e0 = y.e0; }
        if (x.t1 <= y.t1) { r.t1 = x.t1; r.e1 = x.e1; } else { r.t1 = y.t1; r.e1 = y.e1; }
        if (r.t1 - r.t0 > eps) out[n++] = r;
        if (x.t1 <= y.t1) ++i; else ++j;
    }
    return n;
}

int span_difference(const Span* m, int nm, const Span* s, int ns, Span* out, double eps) {
    int n = 0, j = 0;
    for (int i = 0; i < nm; ++i) {
        const Span& mi = m[i];
        double start = mi.t0;
        SpanEnd start_end = mi.e0;
        while (j < ns && s[j].t1 <= start) ++j;  // ends before this span: no later span needs it
        for (int k = j; k < ns && s[k].t0 < mi.t1; ++k) {
            if (s[k].t0 > start) {
                if (s[k].t0 - start > eps)
                    out[n++] = Span{start, s[k].t0, start_end, cut_end(s[k].e0, mi.inner), mi.inner};
            }
            if (s[k].t1 > start) {
                start = s[k].t1;
                start_end = cut_end(s[k].e1, mi.inner);
            }
        }
        if (mi.t1 - start > eps) out[n++] = Span{start, mi.t1, start_end, mi.e1, mi.inner};
    }
    return n;
}

int span_normalize_union(Span* s, int n, double eps) {
    if (n <= 1) return n;
    auto by_start = [](const Span& x, const Span& y) { return x.t0 < y.t0; };
    if (n <= 16) {
        for (int i = 1; i < n; ++i)
            for (int k = i; k > 0 && by_start(s[k], s[k - 1]); --k) std::swap(s[k], s[k - 1]);
    } else {
        std::sort(s, s + n, by_start);
    }
    int w = 0;
    for (int i = 1; i < n; ++i) {
        if (s[i].t0 <= s[w].t1 + eps) {
            if (s[i].t1 > s[w].t1) {
                s[w].t1 = s[i].t1;
                s[w].e1 = s[i].e1;
            }
        } else {
            s[++w] = s[i];
        }
    }
    return w + 1;
}

}  // namespace kerf::render
