#include "lower/studio.hpp"

#include <algorithm>
#include <cmath>

#include "lower/defaults.hpp"

namespace kerf {

namespace {

// The camera offset across the view that centres the projections
// (pu - c) / (pf - depth) of `points` round 0, the depth fixed: their
// largest plus their smallest falls as c grows, so bisect.
double centring_offset(const std::vector<glm::dvec2>& points, double depth) {
    double lo = points[0].x, hi = points[0].x;
    for (const glm::dvec2& p : points) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    for (int i = 0; i < 200 && lo < hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        double most = -HUGE_VAL, least = HUGE_VAL;
        for (const glm::dvec2& p : points) {
            const double s = (p.x - mid) / (p.y - depth);
            most = std::max(most, s), least = std::min(least, s);
        }
        (most + least > 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

csg::Camera studio_camera(const csg::Aabb& frame, double aspect, const SourceLoc& loc) {
    const csg::Camera fallback = default_camera(frame, loc);  // also the size checks
    const glm::dvec3 centre = 0.5 * (frame.lo + frame.hi);
    const glm::dvec3 f = -glm::normalize(glm::dvec3(1, -1, 0.8));
    const glm::dvec3 r = glm::normalize(glm::cross(f, glm::dvec3(0, 0, 1)));
    const glm::dvec3 u = glm::cross(r, f);
    // The frustum whose side planes make the angles the fill asks for
    // (tangents a across, b up) touches the corners: for each axis the two
    // planes through the extreme corners fix the camera's offset and depth.
    const double b = kStudioFill * std::tan(glm::radians(fallback.fov / 2)), a = b * aspect;
    std::vector<glm::dvec2> across, up;  // corners as (offset along the axis, depth along f)
    double right_x = -HUGE_VAL, left_x = HUGE_VAL, top_y = -HUGE_VAL, bottom_y = HUGE_VAL;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 p = glm::dvec3((k & 1) ? frame.hi.x : frame.lo.x, (k & 2) ? frame.hi.y : frame.lo.y,
                                        (k & 4) ? frame.hi.z : frame.lo.z) - centre;
        const double pr = glm::dot(p, r), pu = glm::dot(p, u), pf = glm::dot(p, f);
        across.push_back({pr, pf}), up.push_back({pu, pf});
        right_x = std::max(right_x, pr - a * pf), left_x = std::min(left_x, pr + a * pf);
        top_y = std::max(top_y, pu - b * pf), bottom_y = std::min(bottom_y, pu + b * pf);
    }
    const double depth_x = (left_x - right_x) / (2 * a), depth_y = (bottom_y - top_y) / (2 * b);
    const double depth = std::min(depth_x, depth_y);  // the farther camera: the tighter axis
    if (!(depth < 0) || !std::isfinite(depth)) return fallback;  // no extent to fill the frame with
    const double cx = depth_x <= depth_y ? 0.5 * (right_x + left_x) : centring_offset(across, depth);
    const double cy = depth_y <= depth_x ? 0.5 * (top_y + bottom_y) : centring_offset(up, depth);
    csg::Camera cam = fallback;
    cam.position = centre + cx * r + cy * u + depth * f;
    cam.look_at = cam.position - depth * f;
    return cam;
}

std::vector<csg::Light> studio_lights(const csg::Camera& camera, const csg::Aabb& frame) {
    const glm::dvec3 centre = 0.5 * (frame.lo + frame.hi);
    double radius = 0.5 * glm::length(frame.hi - frame.lo);
    if (!(radius > 0)) radius = std::max(glm::length(camera.position - camera.look_at), 1e-300) * 0.3;
    // The camera's direction seen from above; a camera looking straight
    // down (or up) takes the default view's.
    glm::dvec3 back(camera.position.x - camera.look_at.x, camera.position.y - camera.look_at.y, 0);
    if (!(glm::length(back) > 1e-9 * glm::length(camera.position - camera.look_at))) back = {1, -1, 0};
    back = glm::normalize(back);
    const glm::dvec3 right(-back.y, back.x, 0);  // forward × up for forward = -back
    const glm::dvec3 z(0, 0, 1);
    csg::Light key;
    key.position = centre + 5 * radius * glm::normalize(-0.9 * right + 0.6 * back + 1.6 * z);
    key.intensity = 1.0;
    key.radius = 0.7 * radius;
    key.samples = 16;
    key.probe = true;  // 5 shadow rays where they agree (lit or umbra): most points
    csg::Light fill;
    fill.position = centre + 5 * radius * glm::normalize(1.0 * right + 0.5 * back + 0.4 * z);
    fill.intensity = 0.4;
    fill.shadows = false;
    return {key, fill};
}

}  // namespace kerf
