// The pinhole and orthographic cameras of docs/spec.md §6: pixel (x, y) in
// full-image coordinates, row 0 at the top, right = forward × up, image plane
// 2·tan(fov/2) high at distance 1 (orthographic: `height` high).
#pragma once
#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::render {

class CameraModel {
public:
    CameraModel(const csg::Camera& camera, int width, int height);
    // Ray through the image point (px, py) in pixels; (x + 0.5, y + 0.5) is
    // pixel (x, y)'s centre. The direction is unit length, so t is the
    // Euclidean distance (orthographic: from the image plane).
    void ray(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const;
    // The same ray with the direction left unnormalised (pinhole: from the
    // eye to the image-plane point; orthographic: unit anyway). For shading,
    // where only the hit point matters: a square root and a division less
    // per pixel (~5 % of a simple render).
    void ray_unnormalised(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const;

private:
    glm::dvec3 position_, forward_, right_, up_;
    double half_w_, half_h_;
    double u_scale_, v_scale_;  // image-plane units per pixel
    double width_, height_;
    bool orthographic_;
};

}  // namespace kerf::render
