// One render's samples: the colour a ray through a point of the image sees
// (the camera, the Whitted shader or the path tracer, the ghosts over
// them), the mean of a pixel's sample pattern, and the pixel stored with
// its --alpha coverage. Shared by every pass of render.cpp and by adaptive
// anti-aliasing (adaptive_aa.cpp).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "render/ghosts.hpp"
#include "render/integrator_path.hpp"
#include "render/pixel_store.hpp"
#include "render/render.hpp"
#include "render/sampler.hpp"
#include "render/shading.hpp"

namespace kerf::render {

class PixelSampler {
public:
    // `ghosts`, `path`: null when the render has none. `alpha`: None for
    // colour without coverage (and for AOVs).
    PixelSampler(const CameraModel& camera, const Shader& shader, const GhostLayers* ghosts, const PathTracer* path,
                 PixelStore& store, Alpha alpha, std::uint64_t seed)
        : camera_(camera), shader_(shader), ghosts_(ghosts), path_(path), store_(store), alpha_(alpha), seed_(seed) {}

    bool alpha() const { return alpha_ != Alpha::None; }
    bool ghosts() const { return ghosts_ != nullptr; }
    const glm::dvec3& miss() const { return shader_.miss(); }
    std::uint64_t seed() const { return seed_; }

    // One sample through (px, py); `surface` as Shader::radiance. Not
    // `traced` (a culled tile): the miss colour.
    glm::dvec3 sample(double px, double py, ThreadState& ts, bool traced, std::uint32_t* surface = nullptr) const;
    // Only the surface a sample through (px, py) would see (Shader::surface).
    std::uint32_t surface(double px, double py, ThreadState& ts, bool traced) const;
    // Depth of field: one sample through (px, py) from lens point `lens`.
    glm::dvec3 lens_sample(double px, double py, glm::dvec2 lens, ThreadState& ts, bool traced) const;
    // The mean of `pattern`'s samples in pixel (x, y).
    glm::dvec3 mean(const SamplePattern& pattern, int x, int y, ThreadState& ts, bool traced) const;

    // Stores pixel (x, y), the mean of `samples` samples, with their
    // coverage (--alpha), and starts the next pixel's coverage at 0.
    void put(int x, int y, const glm::dvec3& c, int samples) const;

    // Coverage: the samples of the pixel being shaded that hit a solid (a
    // sample seeing a ghost over the background counts the ghost's
    // opacity). A pixel is shaded start to end on one thread, so it is a
    // thread-local count, reset per pixel.
    static double covered();
    static void set_covered(double hits);
    // What the last sample added to covered().
    static double last_cover();
    static void set_last_cover(double cover);

private:
    glm::dvec3 trace(const glm::dvec3& o, const glm::dvec3& d, ThreadState& ts, std::uint32_t* surface) const;

    const CameraModel& camera_;
    const Shader& shader_;
    const GhostLayers* ghosts_;
    const PathTracer* path_;
    PixelStore& store_;
    Alpha alpha_;
    std::uint64_t seed_;
};

}  // namespace kerf::render
