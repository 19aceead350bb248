// glsl_mat.cpp: GLSL matrix products (see glsl_math.h for the order).
#include "shading/glsl_math.h"

namespace st::glsl {

glm::vec4 mul(const glm::mat4& m, const glm::vec4& v) {
    glm::vec4 r;
    for (int i = 0; i < 4; ++i) {
        const float a = m[0][i] * v.x, b = m[1][i] * v.y, c = m[2][i] * v.z, d = m[3][i] * v.w;
        r[i] = ((a + b) + c) + d;
    }
    return r;
}

}  // namespace st::glsl
