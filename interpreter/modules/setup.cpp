// The scene statements camera, light, spotlight, background, ambient_occlusion
// and fog (docs/spec.md §6, §12): top level only, all but the lights at most once.
#include <cmath>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {

// A camera or light beyond the renderable range (csg::kRenderableRange).
glm::dvec3 in_range(const Args& a, glm::dvec3 p, const char* name) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(p[i]) > csg::kRenderableRange)
            arg_error(a, std::string(name) + " must lie within " + format_number(csg::kRenderableRange) +
                             " of the origin, got " + format_number(std::abs(p[i])));
    return p;
}

void camera(ModuleCall& c) {
    const Args& a = c.args;
    ModuleState& state = c.state();
    if (state.camera_loc)
        throw SourceError(c.st.loc, "camera is already defined at line " + std::to_string(state.camera_loc->line));
    if (!a.has(0)) arg_error(a, "position is required");
    csg::Camera cam;
    cam.position = in_range(a, arg_vec3(a, 0, "position", {0, 0, 0}), "position");
    cam.look_at = in_range(a, arg_vec3(a, 1, "look_at", {0, 0, 0}), "look_at");
    cam.up = arg_vec3(a, 2, "up", {0, 0, 1});
    cam.fov = arg_number(a, 3, "fov", 40);
    glm::dvec3 dir = cam.look_at - cam.position;
    if (!(glm::length(dir) > 0)) arg_error(a, "position and look_at must differ");
    if (glm::length(dir) < 1 / csg::kRenderableRange)
        arg_error(a, "position and look_at must be at least " + format_number(1 / csg::kRenderableRange) + " apart");
    if (!(glm::length(glm::cross(dir, cam.up)) > 1e-12 * glm::length(dir) * glm::length(cam.up)))
        arg_error(a, "up must not be parallel to the view direction");
    std::string projection = "perspective";
    if (a.has(4)) {
        projection = a[4].is_string() ? a[4].as_string() : "";
        if (projection != "perspective" && projection != "orthographic" && projection != "fisheye" &&
            projection != "panoramic")
            arg_error(a, "projection must be \"perspective\", \"orthographic\", \"fisheye\" or \"panoramic\"");
    }
    cam.orthographic = projection == "orthographic";
    if (projection == "fisheye") cam.projection = csg::Projection::Fisheye;
    if (projection == "panoramic") cam.projection = csg::Projection::Panoramic;
    if (cam.orthographic) {
        cam.height = arg_positive(a, 5, "height", 1);
    } else {
        if (a.has(5)) arg_error(a, "height is only for projection = \"orthographic\"");
        if (cam.projection == csg::Projection::Planar) {
            if (!(cam.fov > 0 && cam.fov < 180)) arg_error(a, "fov must be between 0 and 180, got " + format_number(cam.fov));
        } else {
            // A fisheye sees a half-space by default, a panorama all round.
            cam.fov = arg_number(a, 3, "fov", cam.projection == csg::Projection::Fisheye ? 180 : 360);
            if (!(cam.fov > 0 && cam.fov <= 360))
                arg_error(a, "fov must be above 0 and at most 360 for projection = \"" + projection + "\", got " +
                                 format_number(cam.fov));
        }
    }
    // Depth of field: a thin lens on the pinhole camera only.
    cam.aperture = arg_number(a, 6, "aperture", 0);
    if (!(cam.aperture >= 0 && cam.aperture <= csg::kRenderableRange))
        arg_error(a, "aperture must be a number from 0 to " + format_number(csg::kRenderableRange) + ", got " +
                         format_number(cam.aperture));
    if (cam.aperture > 0 && projection != "perspective")
        arg_error(a, "aperture is only for projection = \"perspective\"");
    if (cam.aperture == 0 && (a.has(7) || a.has(8)))
        arg_error(a, std::string(a.has(7) ? "focal_distance" : "blur_samples") + " is only for a camera with an aperture above 0");
    cam.focal_distance = arg_positive(a, 7, "focal_distance", glm::length(dir));
    if (cam.focal_distance > csg::kRenderableRange)
        arg_error(a, "focal_distance must be at most " + format_number(csg::kRenderableRange) + ", got " +
                         format_number(cam.focal_distance));
    const double blur = arg_number(a, 8, "blur_samples", 16);
    if (!(blur >= 1 && blur <= 4096) || blur != std::floor(blur))
        arg_error(a, "blur_samples must be a whole number from 1 to 4096, got " + format_number(blur));
    cam.blur_samples = static_cast<std::uint32_t>(blur);
    c.graph().graph.camera = cam;
    state.camera_loc = &c.st.loc;
}

// The arguments every light shares, from position `first` on: color,
// intensity, radius, samples, shadows, attenuation.
void light_common(const Args& a, std::size_t first, csg::Light& l) {
    if (a.has(first)) l.color = glm::dvec3(arg_color(a, first, "color"));
    l.intensity = arg_number(a, first + 1, "intensity", 1);
    if (l.intensity < 0) arg_error(a, "intensity must not be negative, got " + format_number(l.intensity));
    l.radius = arg_number(a, first + 2, "radius", 0);
    if (!(l.radius >= 0) || l.radius > csg::kRenderableRange)
        arg_error(a, "radius must be a number from 0 to " + format_number(csg::kRenderableRange) + ", got " +
                         format_number(l.radius));
    const double samples = arg_number(a, first + 3, "samples", 16);
    if (!(samples >= 1 && samples <= 4096) || samples != std::floor(samples))
        arg_error(a, "samples must be a whole number from 1 to 4096, got " + format_number(samples));
    l.samples = static_cast<std::uint32_t>(samples);
    l.shadows = arg_bool(a, first + 4, "shadows", true);
    if (a.has(first + 5)) {
        if (!a[first + 5].is_string() ||
            (a[first + 5].as_string() != "none" && a[first + 5].as_string() != "inverse_square"))
            arg_error(a, "attenuation must be \"none\" or \"inverse_square\", got " + to_repr(a[first + 5]));
        l.inverse_square = a[first + 5].as_string() == "inverse_square";
    }
}

void light(ModuleCall& c) {
    const Args& a = c.args;
    if (a.has(0) == a.has(1)) arg_error(a, "give position or direction (exactly one)");
    csg::Light l;
    if (a.has(0)) {
        l.position = in_range(a, arg_vec3(a, 0, "position", {0, 0, 0}), "position");
    } else {
        l.directional = true;
        glm::dvec3 d = arg_vec3(a, 1, "direction", {0, 0, -1});
        if (!(glm::length(d) > 0)) arg_error(a, "direction must not be zero");
        l.direction = d / glm::length(d);
    }
    light_common(a, 2, l);
    // A distant light is a direction: it has no size to soften shadows
    // with, and no distance to fall off over.
    if (l.directional && l.radius > 0) arg_error(a, "radius is for a light with a position, not a direction");
    if (l.directional && l.inverse_square)
        arg_error(a, "attenuation is for a light with a position, not a direction");
    c.graph().graph.lights.push_back(l);
}

void spotlight(ModuleCall& c) {
    const Args& a = c.args;
    if (!a.has(0)) arg_error(a, "position is required");
    if (!a.has(1)) arg_error(a, "look_at is required");
    csg::Light l;
    l.spot = true;
    l.position = in_range(a, arg_vec3(a, 0, "position", {0, 0, 0}), "position");
    const glm::dvec3 axis = in_range(a, arg_vec3(a, 1, "look_at", {0, 0, 0}), "look_at") - l.position;
    if (!(glm::length(axis) > 0)) arg_error(a, "position and look_at must differ");
    l.direction = axis / glm::length(axis);
    l.spot_angle = arg_number(a, 2, "angle", 30);
    l.spot_falloff = arg_number(a, 3, "falloff", 5);
    if (!(l.spot_angle > 0 && l.spot_angle < 180))
        arg_error(a, "angle must be between 0 and 180 degrees, got " + format_number(l.spot_angle));
    if (!(l.spot_falloff >= 0 && l.spot_angle + l.spot_falloff <= 180))
        arg_error(a, "falloff must be from 0 to 180 - angle degrees, got " + format_number(l.spot_falloff));
    light_common(a, 4, l);
    c.graph().graph.lights.push_back(l);
}

void background(ModuleCall& c) {
    const Args& a = c.args;
    ModuleState& state = c.state();
    if (state.background_loc)
        throw SourceError(c.st.loc,
                          "background is already defined at line " + std::to_string(state.background_loc->line));
    if (!a.has(0)) arg_error(a, "color is required");
    c.graph().graph.background = glm::dvec3(arg_color(a, 0, "color"));
    state.background_loc = &c.st.loc;
}

// ambient_occlusion(samples = 16, distance = inf) (render/ao.hpp): at most once.
void ambient_occlusion(ModuleCall& c) {
    const Args& a = c.args;
    auto& slot = c.graph().graph.ambient_occlusion;
    if (slot) throw SourceError(c.st.loc, "ambient_occlusion is already defined");
    csg::AmbientOcclusion ao;
    const double n = arg_number(a, 0, "samples", 16);
    if (!(n >= 1 && n <= 1024 && n == std::floor(n)))
        arg_error(a, "samples must be a whole number from 1 to 1024, got " + format_number(n));
    ao.samples = int(n);
    ao.distance = arg_number(a, 1, "distance", ao.distance);
    if (!(ao.distance > 0)) arg_error(a, "distance must be positive, got " + format_number(ao.distance));
    slot = ao;
    if (c.path_integrator())
        c.warn("does not apply to --integrator path (bounced light replaces the ambient term); ignored");
}

// fog(distance, color) (csg::Fog): at most once.
void fog(ModuleCall& c) {
    const Args& a = c.args;
    auto& slot = c.graph().graph.fog;
    if (slot) throw SourceError(c.st.loc, "fog is already defined");
    if (!a.has(0)) arg_error(a, "distance is required");
    if (!a.has(1)) arg_error(a, "color is required");
    csg::Fog f;
    f.distance = arg_positive(a, 0, "distance", 1);
    f.color = glm::dvec3(arg_color(a, 1, "color"));
    slot = f;
}

const ModuleEntry kSetup[] = {
    {"camera", ModuleKind::Setup,
     {"position", "look_at", "up", "fov", "projection", "height", "aperture", "focal_distance", "blur_samples"}, camera},
    {"light", ModuleKind::Setup,
     {"position", "direction", "color", "intensity", "radius", "samples", "shadows", "attenuation"}, light},
    {"spotlight", ModuleKind::Setup,
     {"position", "look_at", "angle", "falloff", "color", "intensity", "radius", "samples", "shadows", "attenuation"},
     spotlight},
    {"background", ModuleKind::Setup, {"color"}, background},
    {"ambient_occlusion", ModuleKind::Setup, {"samples", "distance"}, ambient_occlusion},
    {"fog", ModuleKind::Setup, {"distance", "color"}, fog},
};

}  // namespace

std::span<const ModuleEntry> setup_modules() { return kSetup; }

}  // namespace kerf::eval
