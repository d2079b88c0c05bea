#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

namespace kerf::render {

CameraModel::CameraModel(const csg::Camera& c, int width, int height)
    : position_(c.position), width_(width), height_(height), orthographic_(c.orthographic),
      projection_(c.orthographic ? csg::Projection::Planar : c.projection),
      pinhole_(projection_ == csg::Projection::Planar && !c.orthographic) {
    forward_ = c.look_at - c.position;
    if (glm::length(forward_) == 0) forward_ = glm::dvec3(0, 1, 0);  // lowering rejects this; stay finite
    forward_ = glm::normalize(forward_);
    right_ = glm::cross(forward_, c.up);
    if (glm::length(right_) < 1e-12 * glm::length(c.up)) {
        // up parallel to the view: any perpendicular keeps the image defined
        right_ = glm::cross(forward_, std::abs(forward_.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0));
    }
    right_ = glm::normalize(right_);
    up_ = glm::cross(right_, forward_);
    half_h_ = orthographic_ ? c.height / 2 : std::tan(glm::radians(c.fov) / 2);
    half_w_ = half_h_ * width_ / height_;
    // Per-ray work is a multiply-add, not two divisions (~5 % of a simple render).
    u_scale_ = 2 * half_w_ / width_;
    v_scale_ = 2 * half_h_ / height_;
    if (projection_ == csg::Projection::Fisheye) {
        circle_ = std::min(width_, height_) / 2;
        angle_scale_ = glm::radians(c.fov) / 2 / circle_;
    } else if (projection_ == csg::Projection::Panoramic) {
        // fov of longitude across the width, fov / 2 of latitude down the
        // height (POV-Ray's spherical camera): a 2:1 image has square pixels.
        angle_scale_ = glm::radians(c.fov) / width_;
        lat_scale_ = glm::radians(c.fov) / 2 / height_;
    }
    if (projection_ == csg::Projection::Planar && !orthographic_ && c.aperture > 0) {
        lens_radius_ = c.aperture / 2;
        focal_distance_ = c.focal_distance;
    }
}

bool CameraModel::ray_other(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const {
    origin = position_;
    switch (projection_) {
        case csg::Projection::Planar: {
            const double u = px * u_scale_ - half_w_;
            const double v = half_h_ - py * v_scale_;
            if (orthographic_) {
                origin = position_ + u * right_ + v * up_;
                direction = forward_;
            } else {
                direction = forward_ + u * right_ + v * up_;
            }
            return true;
        }
        case csg::Projection::Fisheye: {
            // Equidistant: the angle from the axis grows linearly with the
            // distance from the image centre, fov/2 at the circle's rim.
            const double x = px - width_ / 2, y = height_ / 2 - py;
            const double r = std::sqrt(x * x + y * y);
            if (r > circle_) return false;
            const double theta = r * angle_scale_;
            const double s = r > 0 ? std::sin(theta) / r : 0;
            direction = std::cos(theta) * forward_ + (s * x) * right_ + (s * y) * up_;
            return true;
        }
        case csg::Projection::Panoramic: {
            // Equirectangular: longitude from the view direction to the
            // right, latitude up from the horizon (up ⟂ forward).
            const double lon = (px - width_ / 2) * angle_scale_, lat = (height_ / 2 - py) * lat_scale_;
            const double cl = std::cos(lat);
            direction = (cl * std::cos(lon)) * forward_ + (cl * std::sin(lon)) * right_ + std::sin(lat) * up_;
            return true;
        }
    }
    return false;
}

void CameraModel::ray_through_lens(double px, double py, glm::dvec2 lens, glm::dvec3& origin,
                                   glm::dvec3& direction) const {
    const double u = px * u_scale_ - half_w_;
    const double v = half_h_ - py * v_scale_;
    // The pinhole ray's direction has forward component 1: it meets the
    // plane of sharp focus at focal_distance times it.
    const glm::dvec3 focus = position_ + focal_distance_ * (forward_ + u * right_ + v * up_);
    // Shirley–Chiu concentric mapping of [0,1)² onto the unit disk.
    const double a = 2 * lens.x - 1, b = 2 * lens.y - 1;
    double r = 0, phi = 0;
    if (a * a > b * b) r = a, phi = (M_PI / 4) * (b / a);
    else if (b != 0) r = b, phi = M_PI / 2 - (M_PI / 4) * (a / b);
    r *= lens_radius_;
    origin = position_ + (r * std::cos(phi)) * right_ + (r * std::sin(phi)) * up_;
    direction = focus - origin;
}

bool CameraModel::ray(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const {
    if (!ray_unnormalised(px, py, origin, direction)) return false;
    if (!orthographic_) direction = glm::normalize(direction);
    return true;
}

}  // namespace kerf::render
