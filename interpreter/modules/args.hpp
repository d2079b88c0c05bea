// Typed access to the arguments of builtin modules, with the located
// errors of docs/spec.md §4/§8: every message starts with the module's name and
// points at the statement ("cube: size must be positive, got 0").
#pragma once
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "interpreter/evaluator.hpp"

namespace kerf::eval {

[[noreturn]] void arg_error(const Args& a, const std::string& message);
// An argument value kerf cannot render yet: an error in both dialects (the
// OpenSCAD dialect's warning-and-go-on would render another solid).
[[noreturn]] void arg_unsupported(const Args& a, const std::string& message);

// A finite number (default when not given).
double arg_number(const Args& a, std::size_t i, const char* name, double fallback);
// A finite number > 0.
double arg_positive(const Args& a, std::size_t i, const char* name, double fallback);
bool arg_bool(const Args& a, std::size_t i, const char* name, bool fallback);
// A vector of 3 finite numbers (2 numbers give z = `z2`, when allow2).
glm::dvec3 arg_vec3(const Args& a, std::size_t i, const char* name, glm::dvec3 fallback, bool allow2 = false,
                    double z2 = 0);
// [r,g,b], [r,g,b,a], a CSS name or "#rgb[a]"/"#rrggbb[aa]": rgba in [0,1].
glm::dvec4 arg_color(const Args& a, std::size_t i, const char* name);
// A 4x4 or 3x4 affine matrix of finite numbers, rows first (multmatrix's m);
// a 4x4 one must end in the row [0, 0, 0, 1].
glm::dmat4 arg_matrix(const Args& a, std::size_t i, const char* name);

}  // namespace kerf::eval
