#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "tests/render/primitives/prim_check.hpp"

using namespace kerf::test;
using kerf::csg::PrimKind;

TEST_CASE("torus: random rays against the oracle, all scales and thin tori", "[prim][torus][accuracy]") {
    random_suite("torus r/R=0.25", [](double s) { return make_leaf(PrimKind::Torus, {s, 0.25 * s}); }, 16, 16, 12000,
                 3000, 501);
    random_suite("torus r/R=0.9", [](double s) { return make_leaf(PrimKind::Torus, {s, 0.9 * s}); }, 16, 16, 6000,
                 2000, 502);
    random_suite("torus r/R=1e-3", [](double s) { return make_leaf(PrimKind::Torus, {s, 1e-3 * s}); }, 16, 16, 6000,
                 2000, 503);
}

TEST_CASE("thin tori: rays aimed at the tube", "[prim][torus][accuracy]") {
    // Random rays rarely meet a thin tube; aim at points of the core circle.
    for (double ratio : {1e-2, 1e-3}) {
        for (double s : {1e-6, 1.0, 1e6}) {
            const auto leaf = make_leaf(PrimKind::Torus, {s, ratio * s});
            RayGen gen(509);
            CheckStats st, sf;
            for (int i = 0; i < 20000; ++i) {
                const double phi = gen.uniform(0, 6.283185307179586);
                const dvec3 aim = s * dvec3(std::cos(phi), std::sin(phi), 0) + ratio * s * gen.unit() * 1.2;
                const dvec3 u = gen.unit();
                const double back = i % 4 == 0 ? 1e3 * s : s * gen.uniform(0, 3);
                check_ray<double>(leaf, aim - back * u, u * gen.uniform(0.1, 10), 16, s, st);
                check_ray<float>(leaf, aim - back * u, u * gen.uniform(0.1, 10), 16, s, sf);
            }
            INFO("ratio " << ratio << " scale " << s << ": " << st.first_failure << " / " << sf.first_failure);
            CHECK(st.failures == 0);
            CHECK(sf.failures == 0);
            CHECK(st.hits > 5000);
            CHECK(st.flips > st.crossings * 9 / 10);
            report(ratio == 1e-2 ? "torus-aimed r/R=1e-2" : "torus-aimed r/R=1e-3", "double", "near", s, st);
            report(ratio == 1e-2 ? "torus-aimed r/R=1e-2" : "torus-aimed r/R=1e-3", "float", "near", s, sf);
        }
    }
}

TEMPLATE_TEST_CASE("torus: closed-form crossings", "[prim][torus]", float, double) {
    const double eps = std::numeric_limits<TestType>::epsilon();
    for (double s : {1e-6, 1.0, 1e6}) {
        for (double ratio : {0.25, 1e-3}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            const double tol = 64 * eps * s;
            INFO("scale " << s << " ratio " << ratio);
            // Through the centre along x: both sides of the tube.
            CHECK(compare_spans<TestType>(leaf, {-3 * s, 0, 0}, {1, 0, 0},
                                          {{3 * s - R - r, 3 * s - R + r}, {3 * s + R - r, 3 * s + R + r}}, tol) == "");
            // The same from far away (1e3 sizes), un-normalised direction.
            CHECK(compare_spans<TestType>(leaf, {0, -1e3 * s, 0}, {0, 4, 0},
                                          {{(1e3 * s - R - r) / 4, (1e3 * s - R + r) / 4},
                                           {(1e3 * s + R - r) / 4, (1e3 * s + R + r) / 4}},
                                          1e3 * tol) == "");
            // Down the axis through the hole: no span.
            CHECK(compare_spans<TestType>(leaf, {0, 0, 5 * s}, {0, 0, -1}, {}, 0) == "");
            // Vertically through the tube's core circle.
            CHECK(compare_spans<TestType>(leaf, {R, 0, 2 * s}, {0, 0, -1}, {{2 * s - r, 2 * s + r}}, tol) == "");
            // Starting on the outer equator, going inward along -x.
            CHECK(compare_spans<TestType>(leaf, {R + r, 0, 0}, {-1, 0, 0}, {{0, 2 * r}, {2 * R, 2 * R + 2 * r}},
                                          tol) == "");
        }
    }
}

TEST_CASE("torus: grazing the top of the tube down to 1e-9", "[prim][torus]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        for (double ratio : {0.25, 1e-3}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            for (double delta : {1e-3, 1e-6, 1e-9}) {
                // Along x at height z: crosses the tube where (|x| - R)² = r² - z².
                const double z = r * (1 - delta), w = std::sqrt((r - z) * (r + z));
                const double x0 = -3 * s;
                const double tol = 8 * 0x1p-52 * s * s / w;
                INFO("scale " << s << " ratio " << ratio << " delta " << delta);
                CHECK(compare_spans<double>(leaf, {x0, 0, z}, {1, 0, 0},
                                            {{-x0 - R - w, -x0 - R + w}, {-x0 + R - w, -x0 + R + w}}, tol) == "");
                CHECK(compare_spans<double>(leaf, {x0, 0, r * (1 + delta)}, {1, 0, 0}, {}, 0) == "");
            }
        }
    }
}

TEST_CASE("torus: grazing the outer and inner equators down to 1e-9", "[prim][torus]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        for (double ratio : {0.25, 1e-3}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            const double x0 = -3 * s;
            for (double delta : {1e-3, 1e-6, 1e-9}) {
                INFO("scale " << s << " ratio " << ratio << " delta " << delta);
                // In the plane z = 0 along x at y = y0: inside where (R-r)² < x² + y0² < (R+r)².
                // Outer silhouette: one short span, or nothing.
                const double yo = (R + r) * (1 - delta), wo = std::sqrt((R + r - yo) * (R + r + yo));
                CHECK(compare_spans<double>(leaf, {x0, yo, 0}, {1, 0, 0}, {{-x0 - wo, -x0 + wo}},
                                            8 * 0x1p-52 * s * s / wo) == "");
                CHECK(compare_spans<double>(leaf, {x0, (R + r) * (1 + delta), 0}, {1, 0, 0}, {}, 0) == "");
                // Inner silhouette: just inside the hole two spans with a short gap;
                // just past it one span (the line touches the hole's wall from inside).
                const double yi = (R - r) * (1 - delta), gi = std::sqrt((R - r - yi) * (R - r + yi));
                const double wi = std::sqrt((R + r - yi) * (R + r + yi));
                CHECK(compare_spans<double>(leaf, {x0, yi, 0}, {1, 0, 0}, {{-x0 - wi, -x0 - gi}, {-x0 + gi, -x0 + wi}},
                                            8 * 0x1p-52 * s * s / gi) == "");
                const double yp = (R - r) * (1 + delta), wp = std::sqrt((R + r - yp) * (R + r + yp));
                CHECK(compare_spans<double>(leaf, {x0, yp, 0}, {1, 0, 0}, {{-x0 - wp, -x0 + wp}},
                                            64 * 0x1p-52 * s) == "");
            }
        }
    }
}

// The solve starts each crossing from a model of the quartic and takes
// Newton steps without confirming them, and isolates the roots with a first
// guess of the turning point unless F there is undecided: these rays are
// where a wrong start, an unconfirmed step or a wrong guess would show.
TEST_CASE("torus: lines tangent to the tube anywhere, just inside and just outside", "[prim][torus][accuracy]") {
    for (double s : {1e-6, 1.0, 1e6}) {
        for (double ratio : {0.25, 1e-3, 1e-4}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            RayGen gen(511);
            CheckStats st, sf;
            int wrong = 0;
            std::string first;
            for (int i = 0; i < 3000; ++i) {
                const double phi = gen.uniform(0, 6.283185307179586);
                // Top, outer and inner equators first, then anywhere on the tube.
                const double theta = i % 4 == 0 ? 1.5707963267948966 : i % 4 == 1 ? 0.0
                                     : i % 4 == 2 ? 3.141592653589793 : gen.uniform(0, 6.283185307179586);
                const dvec3 c(std::cos(phi), std::sin(phi), 0);
                const dvec3 n = std::cos(theta) * c + dvec3(0, 0, std::sin(theta));
                const dvec3 x = R * c + r * n;  // on the surface, outward normal n
                dvec3 t = gen.unit();
                t = glm::normalize(t - glm::dot(t, n) * n);
                const double back = i % 2 ? 2 * s : 1e3 * s;
                // Offsets along the normal, from 1e6 down to 64 times the
                // tolerance band at the foot (capped inside the tube).
                const double band = 16 * 0x1p-52 * (s + back + glm::length(x));
                for (double k : {1e6, 1e3, 64.0}) {
                    const double off = std::min(k * band, 0.5 * r) * (i % 3 ? 1 : -1);
                    const dvec3 foot = x + off * n, dir = t * gen.uniform(0.1, 10);
                    const dvec3 o = foot - back * t;
                    kerf::csg::Span<double> sp[kerf::csg::kMaxSpans];
                    const int m = check_ray<double>(leaf, o, dir, 16, s, st, sp);
                    check_ray<float>(leaf, o, dir, 16, s, sf);
                    // The foot is inside by |off| or outside by off: in a span or not.
                    const double tf = back / glm::length(dir);
                    bool in = false;
                    for (int j = 0; j < m; ++j) in |= sp[j].t0 < tf && tf < sp[j].t1;
                    if (in != (off < 0) && wrong++ == 0) first = describe(leaf, o, dir);
                }
            }
            INFO("scale " << s << " ratio " << ratio << ": " << first << " | " << st.first_failure << " / "
                          << sf.first_failure);
            CHECK(wrong == 0);
            CHECK(st.failures == 0);
            CHECK(sf.failures == 0);
        }
    }
}

TEST_CASE("torus: horizontal lines grazing the hole's wall at any height and bearing", "[prim][torus]") {
    RayGen gen(512);
    for (double s : {1e-6, 1.0, 1e6}) {
        for (double ratio : {0.25, 1e-3, 1e-4}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            for (double h : {0.0, 0.5, 0.99}) {
                // At height z the tube's section is the annulus R - w < ρ < R + w.
                const double z = h * r, w = std::sqrt((r - z) * (r + z));
                for (double delta : {1e-3, 1e-6, 1e-9}) {
                    const double phi = gen.uniform(0, 6.283185307179586);
                    const dvec3 dir(std::cos(phi), std::sin(phi), 0), side(-std::sin(phi), std::cos(phi), 0);
                    for (double y : {R - w * (1 + delta), R - w * (1 - delta)}) {
                        const dvec3 o = -3 * s * dir + y * side + dvec3(0, 0, z);
                        const double so = std::sqrt((R + w - y) * (R + w + y));
                        INFO("scale " << s << " ratio " << ratio << " height " << h << " delta " << delta << " y " << y);
                        if (y < R - w) {  // through the hole: two spans around a short gap
                            const double si = std::sqrt((R - w - y) * (R - w + y));
                            CHECK(compare_spans<double>(leaf, o, dir, {{3 * s - so, 3 * s - si}, {3 * s + si, 3 * s + so}},
                                                        64 * 0x1p-52 * s * s / si) == "");
                        } else {  // touching the wall from inside the tube: one span
                            CHECK(compare_spans<double>(leaf, o, dir, {{3 * s - so, 3 * s + so}},
                                                        64 * 0x1p-52 * s * s / so) == "");
                        }
                    }
                }
            }
        }
    }
}

TEST_CASE("torus: thin tori (r/R = 1e-4, 1e-6) seen from 1e6 sizes away", "[prim][torus][accuracy]") {
    for (double ratio : {1e-4, 1e-6}) {
        for (double s : {1e-6, 1.0, 1e6}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            // Straight down through the core circle: the span [D - r, D + r].
            const double D = 1e6 * s;
            CHECK(compare_spans<double>(leaf, {0, R, D}, {0, 0, -1}, {{D - r, D + r}}, 16 * 0x1p-52 * 2 * D) == "");
            RayGen gen(513);
            CheckStats st;
            for (int i = 0; i < 4000; ++i) {
                const double phi = gen.uniform(0, 6.283185307179586);
                const dvec3 aim = s * dvec3(std::cos(phi), std::sin(phi), 0) + 0.9 * r * gen.unit();
                const dvec3 u = gen.unit();
                check_ray<double>(leaf, aim - D * u, u * gen.uniform(0.1, 10), 16, s, st);
            }
            INFO("ratio " << ratio << " scale " << s << ": " << st.first_failure);
            CHECK(st.failures == 0);
            CHECK(st.hits == st.rays);  // every ray aims inside the tube
        }
    }
}

TEMPLATE_TEST_CASE("torus: a window gives the same spans inside it", "[prim][torus][window]", float, double) {
    // intersect_leaf's window contract: span ends inside [wa, wb] are what
    // the unwindowed solve gives (to the solver's tolerance: a root found
    // from a narrower bracket may differ in the last bits); ends outside may
    // move, but only to another point on the same side of the window. So
    // coverage anywhere inside the window is unchanged. Rays aimed at the
    // tube, windows starting inside, before and after the tube's spans.
    using T = TestType;
    const T tol = T(64) * std::numeric_limits<T>::epsilon() * T(4);  // |t| <= 4 here
    for (const double ratio : {0.25, 1e-3}) {
        const auto leaf = make_leaf(PrimKind::Torus, {1.0, ratio});
        RayGen gen(811);
        int moved_ends = 0, windows = 0;
        for (int i = 0; i < 20000; ++i) {
            const double phi = gen.uniform(0, 6.283185307179586);
            const dvec3 aim = dvec3(std::cos(phi), std::sin(phi), 0) + ratio * 1.2 * gen.unit();
            const dvec3 u = gen.unit();
            const glm::vec<3, T> o(aim - 3.0 * u), d(u * gen.uniform(0.5, 2));
            kerf::csg::Span<T> full[kerf::csg::kMaxSpans], part[kerf::csg::kMaxSpans];
            const int nf = kerf::csg::intersect_leaf<T>(leaf, o, d, full);
            if (nf == 0) continue;
            const kerf::csg::Span<T>& s = full[i % nf];
            const T len = s.t1 - s.t0;
            const T wa = T(i % 3 == 0 ? s.t0 + 0.3 * len : s.t0 - len * gen.uniform(-0.5, 0.5));
            const T wb = T(wa + len * gen.uniform(0.05, 1.5));
            const int np = kerf::csg::intersect_leaf<T>(leaf, o, d, part, wa, wb);
            ++windows;
            auto near_end = [&](const kerf::csg::Span<T>* sp, int n, T t) {
                for (int k = 0; k < n; ++k)
                    if (std::abs(sp[k].t0 - t) <= tol || std::abs(sp[k].t1 - t) <= tol) return true;
                return false;
            };
            auto covered = [](const kerf::csg::Span<T>* sp, int n, T t) {
                for (int k = 0; k < n; ++k)
                    if (sp[k].t0 < t && t < sp[k].t1) return true;
                return false;
            };
            INFO("ratio " << ratio << " ray " << i << " window " << wa << " .. " << wb);
            // Every end inside the window appears in both lists; an end of
            // the windowed list found in neither is outside the window.
            for (int k = 0; k < nf; ++k)
                for (const T e : {full[k].t0, full[k].t1})
                    if (e > wa + tol && e < wb - tol) CHECK(near_end(part, np, e));
            for (int m = 0; m < np; ++m)
                for (const T e : {part[m].t0, part[m].t1})
                    if (!near_end(full, nf, e)) {
                        CHECK((e <= wa + tol || e >= wb - tol));
                        ++moved_ends;
                    }
            for (int k = 1; k < 16; ++k) {
                const T t = wa + (wb - wa) * T(k) / T(16);
                if (!near_end(full, nf, t)) CHECK(covered(full, nf, t) == covered(part, np, t));
            }
        }
        INFO(windows << " windows, " << moved_ends << " ends not solved");
        CHECK(windows > 10000);
        CHECK(moved_ends > windows / 4);  // the window must actually save solves
    }
}

namespace {

// A windowed torus solve checked against the point-membership oracle on the
// window alone: span ends inside [wa, wb] lie on the surface (within the
// K = 16 band of docs/accuracy.md) and every sample of the window farther
// than the band from the surface is inside exactly when a span covers it.
// Ends outside the window are free (intersect_leaf's contract), so only
// the window is sampled. Returns "" or the first failure.
std::string check_window(const kerf::csg::Leaf& leaf, const dvec3& o, const dvec3& d, double wa, double wb,
                         int& ends_checked) {
    using kerf::csg::Span;
    Span<double> s[kerf::csg::kMaxSpans];
    const int n = kerf::csg::intersect_leaf<double>(leaf, o, d, s, wa, wb);
    const double eps = std::numeric_limits<double>::epsilon(), L = extent(leaf), ol = glm::length(o),
                 dl = glm::length(d);
    const auto band = [&](double t) { return 16 * eps * (L + ol + std::abs(t) * dl); };
    char buf[256];
    const auto where = [&](const char* what, double t) {
        std::snprintf(buf, sizeof buf, "%s at t=%.17g, window %.17g .. %.17g | ", what, t, wa, wb);
        return buf + describe(leaf, o, d);
    };
    for (int i = 0; i < n; ++i) {
        if (!(s[i].t0 < s[i].t1)) return where("empty span", s[i].t0);
        if (i > 0 && !(s[i - 1].t1 < s[i].t0)) return where("spans overlap", s[i].t0);
        for (const double t : {s[i].t0, s[i].t1}) {
            // An end at the window's own end is the window's (its mapping
            // to the solver's frame and back may round an ulp inwards).
            const double at_end = 8 * eps * (std::abs(wa) + std::abs(wb));
            if (!(t > wa + at_end && t < wb - at_end)) continue;
            ++ends_checked;
            if (!(std::abs(kerf::csg::surface_distance(leaf, o + t * d)) <= band(t))) return where("end off the surface", t);
        }
    }
    // Inside the window only: a span through an end is reported from or to
    // (the rounding of) that end.
    for (int k = 1; k < 64; ++k) {
        const double t = wa + (wb - wa) * k / 64.0;
        const dvec3 x = o + t * d;
        if (std::abs(kerf::csg::surface_distance(leaf, x)) <= band(t)) continue;
        bool in = false;
        for (int i = 0; i < n; ++i) in = in || (s[i].t0 < t && t < s[i].t1);
        if (in != kerf::csg::contains(leaf, x)) return where("membership wrong", t);
    }
    return "";
}

}  // namespace

TEST_CASE("torus: windowed solves at extreme scales, grazing the tube, through the hole, from 1e6 away",
          "[prim][torus][window][accuracy]") {
    // The solver clips the chord to the window before looking for turns or
    // roots; these windows start and end inside the tube, inside the hole,
    // before and after it, on rays that graze the tube along its length
    // (tangent to the surface, 1e-9 of r inside or outside), pass through
    // the hole, or start 1e6 (absolute) from the torus.
    for (const double s : {1e-3, 1.0, 1e4}) {
        for (const double ratio : {0.1, 1e-3}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            RayGen gen(907);
            int rays = 0, hits = 0, ends = 0;
            for (int i = 0; i < 3000; ++i) {
                const double phi = gen.uniform(0, 6.283185307179586), psi = gen.uniform(0, 6.283185307179586);
                const dvec3 radial(std::cos(phi), std::sin(phi), 0), along(-std::sin(phi), std::cos(phi), 0);
                const dvec3 normal = std::cos(psi) * radial + std::sin(psi) * dvec3(0, 0, 1);
                const dvec3 surface = R * radial + r * normal;
                dvec3 aim, u;
                switch (i % 3) {
                    case 0: {  // grazing: tangent to the tube at a surface point, just inside or outside
                        const dvec3 side = glm::cross(normal, along);
                        const double a = gen.uniform(0, 3.141592653589793);
                        u = std::cos(a) * along + std::sin(a) * side;
                        aim = surface + (i % 2 ? 1e-9 : -1e-9) * r * normal;
                        break;
                    }
                    case 1: {  // through the hole, steep or slanted enough to touch the inner wall
                        aim = (R - r) * gen.uniform(0, 1.05) * radial;
                        u = glm::normalize(dvec3(0, 0, 1) + gen.uniform(0, 2) * gen.unit());
                        break;
                    }
                    default: {  // aimed inside the tube
                        aim = R * radial + 0.9 * r * gen.uniform(0, 1) * gen.unit();
                        u = gen.unit();
                    }
                }
                const double back = i % 5 == 0 ? 1e6 : 3 * (R + r);
                const dvec3 o = aim - back * u, d = u * gen.uniform(0.5, 2);
                kerf::csg::Span<double> full[kerf::csg::kMaxSpans];
                const int nf = kerf::csg::intersect_leaf<double>(leaf, o, d, full);
                ++rays;
                if (nf == 0) continue;
                ++hits;
                // Windows from the spans' own ends: starting inside a span,
                // ending inside one, inside a gap (the hole), around all.
                const double t_aim = back / glm::length(d);
                const double lo = full[0].t0, hi = full[nf - 1].t1, mid = full[i % nf].t0 + 0.5 * (full[i % nf].t1 - full[i % nf].t0);
                const double windows[][2] = {{mid, hi + (hi - lo)}, {lo - (hi - lo), mid},
                                             {mid, mid + 0.25 * (hi - lo)}, {t_aim - 0.5 * (hi - lo), t_aim + 0.5 * (hi - lo)},
                                             {nf > 1 ? 0.5 * (full[0].t1 + full[1].t0) : mid, hi}};
                for (const auto& w : windows) {
                    INFO("scale " << s << " r/R " << ratio << " ray " << i);
                    const std::string fail = check_window(leaf, o, d, w[0], w[1], ends);
                    REQUIRE(fail == "");
                }
            }
            INFO("scale " << s << " r/R " << ratio << ": " << hits << " of " << rays << " rays hit, " << ends
                          << " ends inside windows");
            CHECK(hits > rays / 2);
            CHECK(ends > hits);
        }
    }
}

TEST_CASE("torus: windows from inside the tube on lines near the ring's plane, convex or not",
          "[prim][torus][window][accuracy]") {
    // A window that starts (or ends) inside the tube skips the turns when F
    // is convex on it (one crossing at most): F'' = 2·(uu - K/ρ³) changes
    // sign only near the axis or on lines nearly in the ring's plane that
    // pass inside the ring (h < α). These lines sweep that boundary: in or
    // near the plane, at distances h from the axis around the inner wall,
    // so some leave the tube into the hole and re-enter it across (two
    // spans, F concave between) and others stay in it or graze the wall. A
    // convexity proof that wrongly accepts such a line loses its second span.
    for (const double s : {1e-3, 1.0, 1e4}) {
        for (const double ratio : {0.1, 0.25, 1e-3}) {
            const double R = s, r = ratio * s;
            const auto leaf = make_leaf(PrimKind::Torus, {R, r});
            RayGen gen(1811);
            int two = 0, one = 0, ends = 0;
            for (int i = 0; i < 2000; ++i) {
                const double phi = gen.uniform(0, 6.283185307179586);
                const dvec3 radial(std::cos(phi), std::sin(phi), 0), along(-std::sin(phi), std::cos(phi), 0);
                const double z = r * gen.uniform(-0.95, 0.95), w = std::sqrt(r * r - z * z);
                // Around the inner wall at this height: 1 - w, to within w.
                const double h = R - w + w * gen.uniform(-1, 1) * (i % 4 == 0 ? 1e-6 : 1.0);
                const double tilt = i % 3 == 0 ? 0.0 : ratio * gen.uniform(-0.2, 0.2);
                const dvec3 u = glm::normalize(along + dvec3(0, 0, tilt));
                const dvec3 aim = h * radial + dvec3(0, 0, z);
                const double back = i % 5 == 0 ? 1e6 : 3 * (R + r);
                const dvec3 o = aim - back * u, d = u * gen.uniform(0.5, 2);
                kerf::csg::Span<double> full[kerf::csg::kMaxSpans];
                const int nf = kerf::csg::intersect_leaf<double>(leaf, o, d, full);
                if (nf == 0) continue;
                (nf == 2 ? two : one)++;
                const double lo = full[0].t0, hi = full[nf - 1].t1;
                for (int k = 0; k < nf; ++k) {
                    const double a = full[k].t0, b = full[k].t1;
                    const double windows[][2] = {{a + 0.3 * (b - a), hi + (hi - lo)},
                                                 {lo - (hi - lo), a + 0.7 * (b - a)},
                                                 {a + 1e-3 * (b - a), b + 0.1 * (hi - lo)}};
                    for (const auto& win : windows) {
                        INFO("scale " << s << " r/R " << ratio << " ray " << i << " span " << k);
                        REQUIRE(check_window(leaf, o, d, win[0], win[1], ends) == "");
                    }
                }
            }
            INFO("scale " << s << " r/R " << ratio << ": " << two << " lines with two spans, " << one << " with one");
            CHECK(two > 400);
            CHECK(one > 400);
        }
    }
}
