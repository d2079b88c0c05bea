#include "render/camera.hpp"

#include <cmath>

namespace kerf::render {

CameraModel::CameraModel(const csg::Camera& c, int width, int height)
    : position_(c.position), width_(width), height_(height), orthographic_(c.orthographic) {
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
}

void CameraModel::ray_unnormalised(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const {
    const double u = px * u_scale_ - half_w_;
    const double v = half_h_ - py * v_scale_;
    if (orthographic_) {
        origin = position_ + u * right_ + v * up_;
        direction = forward_;
    } else {
        origin = position_;
        direction = forward_ + u * right_ + v * up_;
    }
}

void CameraModel::ray(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const {
    ray_unnormalised(px, py, origin, direction);
    if (!orthographic_) direction = glm::normalize(direction);
}

}  // namespace kerf::render
