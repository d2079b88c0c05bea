// Fisheye (equidistant) and panoramic (equirectangular) cameras against
// their closed forms (csg::Projection): the direction of known pixels, and
// a small sphere put at a known angle found at the predicted pixel.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/camera.hpp"
#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

// Forward +y, up +z, right +x; the camera at the origin.
csg::Camera wide(csg::Projection p, double fov) {
    csg::Camera c;
    c.position = {0, 0, 0};
    c.look_at = {0, 5, 0};
    c.up = {0, 0, 1};
    c.projection = p;
    c.fov = fov;
    return c;
}

// The unit direction `polar` degrees from forward, turned `around` degrees
// from right towards up (fisheye), or at longitude/latitude (panoramic).
glm::dvec3 off_axis(double polar, double around) {
    const double t = glm::radians(polar), a = glm::radians(around);
    return {std::sin(t) * std::cos(a), std::cos(t), std::sin(t) * std::sin(a)};
}
glm::dvec3 lon_lat(double lon, double lat) {
    const double o = glm::radians(lon), a = glm::radians(lat);
    return {std::cos(a) * std::sin(o), std::cos(a) * std::cos(o), std::sin(a)};
}

// The centroid of the pixels that see a sphere of radius 0.8 at distance 10
// in direction `dir`, from the depth AOV.
glm::dvec2 where_seen(const csg::Camera& c, glm::dvec3 dir, int w, int h, int* count = nullptr) {
    csg::Scene s = make_scene(leaf(sphere(0.8, translate(10 * dir.x, 10 * dir.y, 10 * dir.z))));
    s.camera = c;
    render::RenderOptions o;
    o.width = w, o.height = h;
    o.aov = render::Aov::Depth;
    const render::Image im = render::render(s, o);
    glm::dvec2 sum(0.0);
    int n = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (std::isfinite(im.at(x, y, 0))) sum += glm::dvec2(x + 0.5, y + 0.5), ++n;
    if (count) *count = n;
    return n ? sum / double(n) : glm::dvec2(-1);
}

}  // namespace

TEST_CASE("fisheye rays: the angle from the axis grows linearly to fov/2 at the image circle", "[camera][wide]") {
    const int W = 60, H = 40;  // the circle: radius 20 about (30, 20)
    for (double fov : {180.0, 360.0, 90.0}) {
        const render::CameraModel cam(wide(csg::Projection::Fisheye, fov), W, H);
        glm::dvec3 o, d;
        REQUIRE(cam.ray(30, 20, o, d));
        CHECK(glm::length(d - glm::dvec3(0, 1, 0)) < 1e-12);
        CHECK(o == glm::dvec3(0));
        for (double r : {5.0, 12.5, 19.999})
            for (double around : {0.0, 30.0, 135.0, 250.0}) {
                const double a = glm::radians(around);
                REQUIRE(cam.ray(30 + r * std::cos(a), 20 - r * std::sin(a), o, d));  // image y grows downwards
                const glm::dvec3 want = off_axis(r / 20 * fov / 2, around);  // (the rim itself is a rounding away)
                INFO("fov " << fov << " r " << r << " around " << around);
                CHECK(glm::length(d - want) < 1e-12);
            }
        CHECK_FALSE(cam.ray(30 + 20.01, 20, o, d));  // outside the circle: no ray
        CHECK_FALSE(cam.ray(1, 1, o, d));
    }
}

TEST_CASE("panoramic rays: fov of longitude across the width, fov/2 of latitude down the height", "[camera][wide]") {
    const int W = 80, H = 40;
    const render::CameraModel full(wide(csg::Projection::Panoramic, 360), W, H);
    glm::dvec3 o, d;
    for (double lon : {-180.0, -135.0, -20.0, 0.0, 45.0, 90.0, 179.0})
        for (double lat : {-90.0, -60.0, 0.0, 10.0, 89.0}) {
            REQUIRE(full.ray(W / 2.0 + lon / 360 * W, H / 2.0 - lat / 180 * H, o, d));
            INFO("lon " << lon << " lat " << lat);
            CHECK(glm::length(d - lon_lat(lon, lat)) < 1e-12);
        }
    // A narrower panorama stretches the same rule: 120° across, 60° down.
    const render::CameraModel part(wide(csg::Projection::Panoramic, 120), 60, 60);
    REQUIRE(part.ray(60, 0, o, d));
    CHECK(glm::length(d - lon_lat(60, 30)) < 1e-12);
}

TEST_CASE("a small sphere at a known angle appears at the predicted pixel", "[render][wide]") {
    SECTION("fisheye") {
        const int W = 240, H = 200;  // circle radius 100 about (120, 100)
        for (double fov : {180.0, 300.0}) {
            const csg::Camera c = wide(csg::Projection::Fisheye, fov);
            for (auto [polar, around] : {std::pair{60.0, 30.0}, std::pair{20.0, 200.0}, std::pair{110.0, -70.0}}) {
                if (polar > fov / 2) continue;
                const double r = polar / (fov / 2) * 100, a = glm::radians(around);
                int n = 0;
                const glm::dvec2 at = where_seen(c, off_axis(polar, around), W, H, &n);
                INFO("fov " << fov << " polar " << polar << " around " << around << " seen at " << at.x << ", " << at.y);
                CHECK(n > 20);
                CHECK(at.x == Approx(120 + r * std::cos(a)).margin(0.35));
                CHECK(at.y == Approx(100 - r * std::sin(a)).margin(0.35));
            }
        }
        // Behind the camera is outside a 180° fisheye's view.
        int n = 1;
        where_seen(wide(csg::Projection::Fisheye, 180), off_axis(120, 0), W, H, &n);
        CHECK(n == 0);
    }
    SECTION("panoramic") {
        const int W = 400, H = 200;
        const csg::Camera c = wide(csg::Projection::Panoramic, 360);
        for (auto [lon, lat] : {std::pair{-135.0, 30.0}, std::pair{100.0, -45.0}, std::pair{10.0, 5.0}}) {
            int n = 0;
            const glm::dvec2 at = where_seen(c, lon_lat(lon, lat), W, H, &n);
            INFO("lon " << lon << " lat " << lat << " seen at " << at.x << ", " << at.y);
            CHECK(n > 20);
            CHECK(at.x == Approx(W / 2.0 + lon / 360 * W).margin(0.35));
            CHECK(at.y == Approx(H / 2.0 - lat / 180 * H).margin(0.35));
        }
    }
}
