// Interval lists of the CSG tracer: where a ray is inside a (sub)solid, with
// enough about each end to shade it (which leaf's surface, outward or
// flipped, exterior or cut-face material). Lists are sorted and disjoint and
// live in a per-thread stack (SpanStack), never on the heap per ray.
#pragma once
#include <cstdint>
#include <vector>

namespace kerf::render {

struct SpanEnd {
    std::uint32_t leaf = 0;      // the leaf whose surface this end lies on
    std::uint32_t mat_leaf = 0;  // the leaf whose material shows here
    std::uint8_t part = 0;       // surface piece, for object_normal()
    std::uint8_t flip = 0;       // 1: the final solid's normal is -(leaf's outward normal)
    std::uint8_t cut = 0;        // 1: a cut face: show mat_leaf's interior colour
    std::uint32_t prim = 0;      // mesh leaves: the triangle hit
};

struct Span {
    double t0, t1;
    SpanEnd e0, e1;
    std::uint32_t inner;  // a leaf whose inside fills the span (exposed by cuts)
};

// Regularised set operations. `eps` is the length below which a span or a
// gap is treated as empty (the degenerate rule: A − A is empty, flush faces
// neither leave slivers nor split unions). Outputs are written to `out`
// (which must not alias the inputs) and the count is returned.
int span_union(const Span* a, int na, const Span* b, int nb, Span* out, double eps);
int span_intersection(const Span* a, int na, const Span* b, int nb, Span* out, double eps);
int span_difference(const Span* m, int nm, const Span* s, int ns, Span* out, double eps);

// Sorts unsorted, possibly overlapping spans in place and merges them into
// their union; returns the new count.
int span_normalize_union(Span* s, int n, double eps);

// A stack of spans shared by the recursive evaluation of one thread. Indices,
// not pointers, survive growth; capacity grows only past the largest list
// this thread has ever needed, so steady-state rendering does not allocate.
class SpanStack {
public:
    SpanStack() { data_.resize(4096); }
    std::uint32_t size() const { return top_; }
    void resize(std::uint32_t n) {
        if (n > data_.size()) data_.resize(std::size_t(n) * 2);
        top_ = n;
    }
    Span* at(std::uint32_t i) { return data_.data() + i; }
    void push(const Span& s) {
        resize(top_ + 1);
        data_[top_ - 1] = s;
    }

private:
    std::vector<Span> data_;
    std::uint32_t top_ = 0;
};

}  // namespace kerf::render
