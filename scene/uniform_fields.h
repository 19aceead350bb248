// uniform_fields.h: a GLSL uniform's value read from a scene file, for a
// scene kind that passes uniforms through from its file (the kind
// `shadertwin new-technique` writes). One field per uniform, named as the
// uniform, whose JSON follows the GLSL type:
//   float, double         a number
//   int, uint             a whole number, an int32's or a uint32's
//   bool                  true or false
//   vecN, dvecN, ivecN, uvecN  N numbers;  bvecN: N booleans
//   matN, matCxR, dmatN, dmatCxR  N*N (C*R) numbers, column-major as
//                         glUniformMatrix*fv takes them, or "identity"
//   T name[K]             an array of K values of T, set as name[0] ...
// Floats lie within +-1e6 (a radiance or a coordinate a scene needs; a
// product of two then stays finite); doubles are taken as JSON gives them.
#pragma once

#include <string>
#include <vector>

#include "frame/frame.h"
#include "scene/json_reader.h"

namespace st {

// Whether read_uniform_field reads `glsl_type` (not a sampler or a struct;
// those a kind reads itself).
bool is_uniform_field_type(const std::string& glsl_type);

// Appends the uniform(s) the field `key` of `r` holds: one for a value,
// array_size for an array (0: not an array). `gl_name` is the name GL knows
// the uniform by (a struct member's "light.colour"); empty: `key`.
// InputError naming the field when it is missing or out of its domain.
void read_uniform_field(JsonReader& r, const std::string& key, const std::string& glsl_type, int array_size,
                        std::vector<Uniform>& out, const std::string& gl_name = "");

}  // namespace st
