#include "cli/view/camera_text.hpp"

#include <charconv>
#include <cmath>

#include <glm/geometric.hpp>

#include "cli/view/json.hpp"

namespace kerf::view {

namespace {

bool parse_double(const std::string& text, double& v) {
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(v) &&
           std::abs(v) <= csg::kRenderableRange;
}

bool parse_vec3(const std::string& text, glm::dvec3& v) {
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text.find(',', start);
        if ((i < 2) != (comma != std::string::npos)) return false;
        if (!parse_double(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start), v[i]))
            return false;
        start = comma + 1;
    }
    return true;
}

std::string vec3(const glm::dvec3& v) {
    return "[" + json_number(v.x) + ", " + json_number(v.y) + ", " + json_number(v.z) + "]";
}

}  // namespace

std::optional<csg::Camera> camera_from_query(const std::multimap<std::string, std::string>& params, std::string* error) {
    auto get = [&](const char* key) -> const std::string* {
        auto it = params.find(key);
        return it == params.end() ? nullptr : &it->second;
    };
    csg::Camera c;
    const std::string *pos = get("position"), *at = get("look_at"), *up = get("up"), *fov = get("fov"),
                      *height = get("height");
    if (!pos || !at || !up || (!fov == !height)) {
        *error = "expected position, look_at, up and one of fov or height";
        return std::nullopt;
    }
    if (!parse_vec3(*pos, c.position) || !parse_vec3(*at, c.look_at) || !parse_vec3(*up, c.up)) {
        *error = "position, look_at and up must be three finite numbers x,y,z";
        return std::nullopt;
    }
    if (fov && (!parse_double(*fov, c.fov) || !(c.fov > 0 && c.fov < 180))) {
        *error = "fov must be a number between 0 and 180";
        return std::nullopt;
    }
    if (height) {
        c.orthographic = true;
        if (!parse_double(*height, c.height) || !(c.height >= 1e-30)) {
            *error = "height must be a positive number";
            return std::nullopt;
        }
    }
    const glm::dvec3 view = c.look_at - c.position;
    const double len = glm::length(view), up_len = glm::length(c.up);
    // The same rules as the camera statement (interpreter/modules/setup.cpp).
    if (!(len >= 1 / csg::kRenderableRange) || !(glm::length(glm::cross(view, c.up)) > 1e-12 * len * up_len)) {
        *error = "the camera needs look_at apart from position and up not along the view";
        return std::nullopt;
    }
    return c;
}

std::string camera_statement(const csg::Camera& c) {
    std::string s = "camera(position = " + vec3(c.position) + ", look_at = " + vec3(c.look_at) + ", up = " + vec3(c.up);
    if (c.orthographic) s += ", projection = \"orthographic\", height = " + json_number(c.height);
    else s += ", fov = " + json_number(c.fov);
    return s + ");";
}

std::string camera_json(const csg::Camera& c) {
    return "{\"position\":" + vec3(c.position) + ",\"look_at\":" + vec3(c.look_at) + ",\"up\":" + vec3(c.up) +
           ",\"fov\":" + json_number(c.fov) + ",\"orthographic\":" + (c.orthographic ? "true" : "false") +
           ",\"height\":" + json_number(c.height) + "}";
}

}  // namespace kerf::view
