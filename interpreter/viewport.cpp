// $vpr, $vpt, $vpd and $vpf set at the main file's top level place the
// default camera as OpenSCAD 2021's viewport does (docs/openscad.md,
// "Viewport"): the camera looks down -z from $vpd above $vpt, turned by
// rotate($vpr) about $vpt, with a vertical field of view of $vpf degrees.
// Those left unset take OpenSCAD's defaults; none set leaves kerf's framing.
#include <cmath>

#include "interpreter/degrees.hpp"
#include "interpreter/evaluator.hpp"

namespace kerf::eval {

void Evaluator::note_viewport(std::string_view name, const Value& v, const SourceLoc* loc) {
    if (name == "$vpr" || name == "$vpt" || name == "$vpd" || name == "$vpf") viewport_.push_back({name, v, loc});
}

namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// OpenSCAD's vec3 reading: three numbers, or two and z = 0.
bool read_vec3(const Value& v, glm::dvec3& out) {
    if (!v.is_vector(3) && !v.is_vector(2)) return false;
    const ValueList& l = v.as_list();
    out = glm::dvec3(l[0].as_number(), l[1].as_number(), l.size() == 3 ? l[2].as_number() : 0);
    return true;
}

}  // namespace

void Evaluator::viewport_camera(const SourceLoc& top) {
    glm::dvec3 rotation(55, 0, 25), target(0);  // OpenSCAD's defaults
    double distance = 140, fov = 22.5;
    bool set = false;
    // OpenSCAD reads them in this order, each once, its last binding.
    for (std::string_view name : {"$vpr", "$vpt", "$vpd", "$vpf"}) {
        const ViewportVar* var = nullptr;
        for (const ViewportVar& v : viewport_)
            if (v.name == name) var = &v;
        if (!var || var->value.is_undef()) continue;  // undef is unset, silently (as OpenSCAD)
        const SourceLoc& loc = var->loc ? *var->loc : top;
        const std::string given = std::string(name) + "=" + to_repr(var->value);
        const bool vector = name == "$vpr" || name == "$vpt";
        glm::dvec3 v(0);
        if (vector ? !read_vec3(var->value, v) : !var->value.is_number()) {
            warn(loc, "Unable to convert " + given + (vector ? " to a vec3 or vec2 of numbers" : " to a number"));
            continue;
        }
        const double x = vector ? 0 : var->value.as_number();
        // Beyond OpenSCAD: values that would give it a blank or broken picture.
        const bool ok = name == "$vpr"   ? finite(v)
                        : name == "$vpt" ? finite(v) && glm::length(v) <= csg::kRenderableRange
                        : name == "$vpd" ? x > 0 && x <= csg::kRenderableRange
                                         : x > 0 && x < 180;
        if (!ok) {
            const char* why = name == "$vpr"   ? "finite angles"
                              : name == "$vpt" ? "a finite point within 1e30 of the origin"
                              : name == "$vpd" ? "a distance above 0 and at most 1e30"
                                               : "a field of view between 0 and 180 degrees";
            warn(loc, given + " is not " + std::string(why) + ": the viewport keeps its default");
            continue;
        }
        set = true;
        if (name == "$vpr") rotation = v;
        else if (name == "$vpt") target = v;
        else if (name == "$vpd") distance = x;
        else fov = x;
    }
    if (!set) return;
    const glm::dmat3 turn(euler_rotation(rotation));
    csg::Camera cam;
    cam.look_at = target;
    cam.position = target + distance * turn[2];
    cam.up = turn[1];
    cam.fov = fov;
    if (!finite(cam.position) || glm::length(cam.position) > csg::kRenderableRange ||
        !(glm::length(cam.position - target) >= 1 / csg::kRenderableRange)) {
        warn(top, "the viewport ($vpr, $vpt, $vpd) puts the camera out of range: kerf frames the model itself");
        return;
    }
    out_.graph.camera = cam;
}

}  // namespace kerf::eval
