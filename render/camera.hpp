// The cameras of docs/spec.md §6 and §12: pixel (x, y) in full-image
// coordinates, row 0 at the top, right = forward × up. Planar: the pinhole
// (image plane 2·tan(fov/2) high at distance 1), the orthographic camera
// (`height` high) and the pinhole's thin lens (depth of field: rays from a
// disk `aperture` across through the point the pinhole ray meets at
// `focal_distance`). Fisheye and panoramic: csg::Projection.
#pragma once
#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::render {

class CameraModel {
public:
    CameraModel(const csg::Camera& camera, int width, int height);
    // Ray through the image point (px, py) in pixels; (x + 0.5, y + 0.5) is
    // pixel (x, y)'s centre. The direction is unit length, so t is the
    // Euclidean distance (orthographic: from the image plane). False where
    // the image shows no ray (outside a fisheye's circle): the background.
    bool ray(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const;
    // The same ray with the direction left unnormalised (pinhole: from the
    // eye to the image-plane point; orthographic: unit anyway). For shading,
    // where only the hit point matters: a square root and a division less
    // per pixel (~5 % of a simple render).
    // The pinhole's (the usual camera) is inline: a call and a switch cost as
    // much as its dozen multiplies and adds, once per pixel.
    bool ray_unnormalised(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const {
        if (!pinhole_) return ray_other(px, py, origin, direction);
        const double u = px * u_scale_ - half_w_;
        const double v = half_h_ - py * v_scale_;
        origin = position_;
        direction = forward_ + u * right_ + v * up_;
        return true;
    }
    // Depth of field: the ray through (px, py) from the lens point that
    // `lens` (in the unit square) maps to by the concentric disk mapping
    // (strata stay strata); unnormalised. Only when has_lens().
    void ray_through_lens(double px, double py, glm::dvec2 lens, glm::dvec3& origin, glm::dvec3& direction) const;
    bool has_lens() const { return lens_radius_ > 0; }
    // Whether a tile's four corner rays bound the rays between them (a
    // pinhole or orthographic camera): then tiles may be culled (tiles.hpp).
    bool corners_bound_tiles() const { return projection_ == csg::Projection::Planar && !has_lens(); }

private:
    // ray_unnormalised for every camera but the pinhole.
    bool ray_other(double px, double py, glm::dvec3& origin, glm::dvec3& direction) const;

    glm::dvec3 position_, forward_, right_, up_;
    double half_w_, half_h_;
    double u_scale_, v_scale_;  // image-plane units per pixel
    double width_, height_;
    bool orthographic_;
    csg::Projection projection_;
    bool pinhole_;              // planar and not orthographic
    double angle_scale_ = 0;    // fisheye, panoramic (across): radians per pixel
    double lat_scale_ = 0;      // panoramic: radians of latitude per pixel row
    double circle_ = 0;         // fisheye: the image circle's radius in pixels
    double lens_radius_ = 0, focal_distance_ = 1;
};

}  // namespace kerf::render
