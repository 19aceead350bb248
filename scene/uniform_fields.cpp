// uniform_fields.cpp: see uniform_fields.h.
#include "scene/uniform_fields.h"

#include <algorithm>
#include <cmath>

#include "scene/input_error.h"

namespace st {

namespace {

constexpr double kMaxFloat = 1e6;

struct TypeInfo {
    UniformType type;
    int count;     // values
    char element;  // 'f' float, 'd' double, 'i' int, 'u' uint, 'b' bool
    int columns = 0, rows = 0;  // a matrix's, else 0
};

bool type_info(const std::string& t, TypeInfo& info) {
    static const struct { const char* name; TypeInfo info; } table[] = {
        {"float", {UniformType::Float, 1, 'f', 0}}, {"vec2", {UniformType::Vec2, 2, 'f', 0}},
        {"vec3", {UniformType::Vec3, 3, 'f', 0}},   {"vec4", {UniformType::Vec4, 4, 'f', 0}},
        {"int", {UniformType::Int, 1, 'i', 0}},     {"ivec2", {UniformType::IVec2, 2, 'i', 0}},
        {"ivec3", {UniformType::IVec3, 3, 'i', 0}}, {"ivec4", {UniformType::IVec4, 4, 'i', 0}},
        {"uint", {UniformType::UInt, 1, 'u', 0}},   {"uvec2", {UniformType::UVec2, 2, 'u', 0}},
        {"uvec3", {UniformType::UVec3, 3, 'u', 0}}, {"uvec4", {UniformType::UVec4, 4, 'u', 0}},
        {"bool", {UniformType::Int, 1, 'b', 0}},    {"bvec2", {UniformType::IVec2, 2, 'b', 0}},
        {"bvec3", {UniformType::IVec3, 3, 'b', 0}}, {"bvec4", {UniformType::IVec4, 4, 'b', 0}},
        {"mat2", {UniformType::Mat2, 4, 'f', 2, 2}},     {"mat3", {UniformType::Mat3, 9, 'f', 3, 3}},
        {"mat4", {UniformType::Mat4, 16, 'f', 4, 4}},    {"mat2x2", {UniformType::Mat2, 4, 'f', 2, 2}},
        {"mat3x3", {UniformType::Mat3, 9, 'f', 3, 3}},   {"mat4x4", {UniformType::Mat4, 16, 'f', 4, 4}},
        {"mat2x3", {UniformType::Mat2x3, 6, 'f', 2, 3}}, {"mat2x4", {UniformType::Mat2x4, 8, 'f', 2, 4}},
        {"mat3x2", {UniformType::Mat3x2, 6, 'f', 3, 2}}, {"mat3x4", {UniformType::Mat3x4, 12, 'f', 3, 4}},
        {"mat4x2", {UniformType::Mat4x2, 8, 'f', 4, 2}}, {"mat4x3", {UniformType::Mat4x3, 12, 'f', 4, 3}},
        {"double", {UniformType::Double, 1, 'd', 0}},     {"dvec2", {UniformType::DVec2, 2, 'd', 0}},
        {"dvec3", {UniformType::DVec3, 3, 'd', 0}},       {"dvec4", {UniformType::DVec4, 4, 'd', 0}},
        {"dmat2", {UniformType::DMat2, 4, 'd', 2, 2}},    {"dmat3", {UniformType::DMat3, 9, 'd', 3, 3}},
        {"dmat4", {UniformType::DMat4, 16, 'd', 4, 4}},   {"dmat2x2", {UniformType::DMat2, 4, 'd', 2, 2}},
        {"dmat3x3", {UniformType::DMat3, 9, 'd', 3, 3}},  {"dmat4x4", {UniformType::DMat4, 16, 'd', 4, 4}},
        {"dmat2x3", {UniformType::DMat2x3, 6, 'd', 2, 3}}, {"dmat2x4", {UniformType::DMat2x4, 8, 'd', 2, 4}},
        {"dmat3x2", {UniformType::DMat3x2, 6, 'd', 3, 2}}, {"dmat3x4", {UniformType::DMat3x4, 12, 'd', 3, 4}},
        {"dmat4x2", {UniformType::DMat4x2, 8, 'd', 4, 2}}, {"dmat4x3", {UniformType::DMat4x3, 12, 'd', 4, 3}},
    };
    for (const auto& e : table)
        if (t == e.name) {
            info = e.info;
            return true;
        }
    return false;
}

// One value of the type from `v`; `field` names it in errors.
Uniform value_of(const nlohmann::json& v, const TypeInfo& info, const std::string& name, const std::string& field) {
    Uniform u{name, info.type, {}};
    if (info.columns && v.is_string() && v.get<std::string>() == "identity") {
        for (int c = 0; c < std::min(info.columns, info.rows); ++c) u.value[size_t(c * info.rows + c)] = 1.0f;
        return u;
    }
    const bool scalar = info.count == 1;
    if (!scalar && (!v.is_array() || v.size() != size_t(info.count)))
        throw InputError("field '" + field + "' must be " + std::to_string(info.count) +
                         (info.element == 'b' ? " booleans" : " numbers") + (info.columns ? " (column-major) or \"identity\"" : ""));
    for (int c = 0; c < info.count; ++c) {
        const nlohmann::json& x = scalar ? v : v[size_t(c)];
        const std::string where = scalar ? field : field + "." + std::to_string(c);
        if (info.element == 'b') {
            if (!x.is_boolean()) throw InputError("field '" + where + "' must be true or false");
            u.value[size_t(c)] = x.get<bool>() ? 1.0f : 0.0f;
            continue;
        }
        if (!x.is_number()) throw InputError("field '" + where + "' must be a number");
        const double d = x.get<double>();
        if (info.element == 'd') {
            if (!std::isfinite(d)) throw InputError("field '" + where + "' must be a finite number");
            u.value[size_t(c)] = d;
            continue;
        }
        if (info.element == 'f') {
            if (!(std::abs(d) <= kMaxFloat)) throw InputError("field '" + where + "' must lie within +-1e6");
            u.value[size_t(c)] = float(d);
            continue;
        }
        // Every int32 or uint32 (the Uniform's double holds each exactly).
        const bool is_unsigned = info.element == 'u';
        const double lo = is_unsigned ? 0.0 : -2147483648.0, hi = is_unsigned ? 4294967295.0 : 2147483647.0;
        if (!(d >= lo && d <= hi) || d != std::floor(d))
            throw InputError("field '" + where + "' must be a whole number in [" +
                             (is_unsigned ? "0, 4294967295]" : "-2147483648, 2147483647]"));
        u.value[size_t(c)] = d;
    }
    return u;
}

}  // namespace

bool is_uniform_field_type(const std::string& glsl_type) {
    TypeInfo info;
    return type_info(glsl_type, info);
}

void read_uniform_field(JsonReader& r, const std::string& key, const std::string& glsl_type, int array_size,
                        std::vector<Uniform>& out, const std::string& gl_name) {
    TypeInfo info;
    if (!type_info(glsl_type, info)) throw std::logic_error("read_uniform_field: no field type for GLSL '" + glsl_type + "'");
    const std::string name = gl_name.empty() ? key : gl_name;
    const std::string field = r.field(key);
    if (array_size == 0) {
        if (!r.has(key)) throw InputError("missing field '" + field + "' (uniform " + glsl_type + " " + name + ")");
        out.push_back(value_of(r.raw(key), info, name, field));
        return;
    }
    const nlohmann::json& values = r.array(key, size_t(array_size), size_t(array_size));
    for (int i = 0; i < array_size; ++i)
        out.push_back(value_of(values[size_t(i)], info, name + "[" + std::to_string(i) + "]", field + "." + std::to_string(i)));
}

}  // namespace st
