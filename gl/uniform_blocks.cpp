// uniform_blocks.cpp: see uniform_blocks.h.
#include "gl/uniform_blocks.h"

#include <cstring>
#include <string>

namespace st {

namespace {

// Columns and rows of a matrix type (0 for others), and whether its values
// are integers (written as int32 or uint32, as std140 holds bool too) or
// doubles (8 bytes each; GL's offsets and strides say where).
struct Shape {
    int columns = 0, rows = 0, components = 1;
    bool integer = false, is_unsigned = false, is_double = false;
};

Shape shape_of(UniformType t) {
    switch (t) {
    case UniformType::Float: return {0, 0, 1};
    case UniformType::Vec2: return {0, 0, 2};
    case UniformType::Vec3: return {0, 0, 3};
    case UniformType::Vec4: return {0, 0, 4};
    case UniformType::Int: return {0, 0, 1, true};
    case UniformType::IVec2: return {0, 0, 2, true};
    case UniformType::IVec3: return {0, 0, 3, true};
    case UniformType::IVec4: return {0, 0, 4, true};
    case UniformType::UInt: return {0, 0, 1, true, true};
    case UniformType::UVec2: return {0, 0, 2, true, true};
    case UniformType::UVec3: return {0, 0, 3, true, true};
    case UniformType::UVec4: return {0, 0, 4, true, true};
    case UniformType::Mat2: return {2, 2};
    case UniformType::Mat3: return {3, 3};
    case UniformType::Mat4: return {4, 4};
    case UniformType::Mat2x3: return {2, 3};
    case UniformType::Mat2x4: return {2, 4};
    case UniformType::Mat3x2: return {3, 2};
    case UniformType::Mat3x4: return {3, 4};
    case UniformType::Mat4x2: return {4, 2};
    case UniformType::Mat4x3: return {4, 3};
    case UniformType::Double: return {0, 0, 1, false, false, true};
    case UniformType::DVec2: return {0, 0, 2, false, false, true};
    case UniformType::DVec3: return {0, 0, 3, false, false, true};
    case UniformType::DVec4: return {0, 0, 4, false, false, true};
    case UniformType::DMat2: return {2, 2, 1, false, false, true};
    case UniformType::DMat3: return {3, 3, 1, false, false, true};
    case UniformType::DMat4: return {4, 4, 1, false, false, true};
    case UniformType::DMat2x3: return {2, 3, 1, false, false, true};
    case UniformType::DMat2x4: return {2, 4, 1, false, false, true};
    case UniformType::DMat3x2: return {3, 2, 1, false, false, true};
    case UniformType::DMat3x4: return {3, 4, 1, false, false, true};
    case UniformType::DMat4x2: return {4, 2, 1, false, false, true};
    case UniformType::DMat4x3: return {4, 3, 1, false, false, true};
    }
    return {};
}

void put(std::vector<uint8_t>& bytes, GLint offset, const void* value, size_t size) {
    if (offset >= 0 && size_t(offset) + size <= bytes.size()) std::memcpy(&bytes[size_t(offset)], value, size);
}

// One value of `s` at `offset`: a double, a float, or an int32 or uint32
// (each exact: the Uniform holds it exactly).
void put_value(std::vector<uint8_t>& bytes, GLint offset, const Shape& s, double v) {
    if (s.is_double) {
        put(bytes, offset, &v, 8);
    } else if (s.integer) {  // int32 or uint32: the same 32 bits
        const uint32_t x = uniform_integer_bits(v);
        put(bytes, offset, &x, 4);
    } else {
        const float x = float(v);
        put(bytes, offset, &x, 4);
    }
}

// One uniform's value at `offset` (a matrix's columns `matrix_stride` apart).
void write(std::vector<uint8_t>& bytes, const Uniform& u, GLint offset, GLint matrix_stride) {
    const Shape s = shape_of(u.type);
    const int size = s.is_double ? 8 : 4;
    if (s.columns) {
        for (int c = 0; c < s.columns; ++c)
            for (int r = 0; r < s.rows; ++r)
                put_value(bytes, offset + c * matrix_stride + r * size, s, u.value[size_t(c * s.rows + r)]);
        return;
    }
    for (int i = 0; i < s.components; ++i) put_value(bytes, offset + i * size, s, u.value[size_t(i)]);
}

const Uniform* named(const std::vector<Uniform>& uniforms, const std::string& name) {
    for (const Uniform& u : uniforms)
        if (u.name == name) return &u;
    return nullptr;
}

}  // namespace

std::vector<UniformBlockData> uniform_block_data(const GlApi& gl, GLuint program, const std::vector<Uniform>& uniforms) {
    GLint blocks = 0;
    gl.GetProgramiv(program, GL_ACTIVE_UNIFORM_BLOCKS, &blocks);
    std::vector<UniformBlockData> out;
    for (GLint b = 0; b < blocks; ++b) {
        UniformBlockData data;
        data.index = GLuint(b);
        GLint size = 0, count = 0;
        gl.GetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_DATA_SIZE, &size);
        gl.GetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS, &count);
        data.bytes.assign(size_t(std::max(size, 0)), 0);
        std::vector<GLint> members(size_t(std::max(count, 0)));
        if (count > 0) gl.GetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES, members.data());
        for (GLint m : members) {
            const GLuint index = GLuint(m);
            GLint offset = 0, array_size = 1, array_stride = 0, matrix_stride = 0, name_length = 0;
            gl.GetActiveUniformsiv(program, 1, &index, GL_UNIFORM_OFFSET, &offset);
            gl.GetActiveUniformsiv(program, 1, &index, GL_UNIFORM_SIZE, &array_size);
            gl.GetActiveUniformsiv(program, 1, &index, GL_UNIFORM_ARRAY_STRIDE, &array_stride);
            gl.GetActiveUniformsiv(program, 1, &index, GL_UNIFORM_MATRIX_STRIDE, &matrix_stride);
            gl.GetActiveUniformsiv(program, 1, &index, GL_UNIFORM_NAME_LENGTH, &name_length);
            std::string name(size_t(std::max(name_length, 1)), '\0');
            GLsizei written = 0;
            gl.GetActiveUniformName(program, index, GLsizei(name.size()), &written, name.data());
            name.resize(size_t(written));
            // An array member is reported once, as "name[0]", with its size.
            const bool array = name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0;
            const std::string base = array ? name.substr(0, name.size() - 3) : name;
            for (GLint i = 0; i < array_size; ++i) {
                const Uniform* u = named(uniforms, array ? base + "[" + std::to_string(i) + "]" : name);
                if (u) write(data.bytes, *u, offset + i * array_stride, matrix_stride);
            }
        }
        out.push_back(std::move(data));
    }
    return out;
}

}  // namespace st
