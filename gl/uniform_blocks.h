// uniform_blocks.h: the contents of a program's uniform blocks (`uniform
// Matrices { mat4 projection; ... };`), filled from the draw's Uniforms as
// GL lays the block out. A scene names a block's members as GL does: a
// block with an instance name by the block's name and the member
// ("Matrices.projection"), one without by the member alone ("projection");
// the twins read them by those names like any uniform. Whatever layout the
// block declares (std140, shared, packed), the offsets, array strides and
// matrix strides come from GL's reflection, so nothing here assumes one.
#pragma once

#include <cstdint>
#include <vector>

#include "frame/frame.h"
#include "gl/gl_api.h"

namespace st {

struct UniformBlockData {
    GLuint index = 0;            // the block's index in the program
    std::vector<uint8_t> bytes;  // its buffer: GL_UNIFORM_BLOCK_DATA_SIZE bytes
};

// One entry per active block; a member no Uniform names stays zero (as the
// twin's Bindings would refuse to read it, the scene fails on the CPU side).
std::vector<UniformBlockData> uniform_block_data(const GlApi& gl, GLuint program, const std::vector<Uniform>& uniforms);

}  // namespace st
