// sampler2d.cpp: nearest and bilinear filtering with llvmpipe's arithmetic.
#include "raster/sampler2d.h"

#include <algorithm>
#include <cmath>

namespace st {

namespace {

int wrap(int i, int size, TextureWrap mode) {
    if (mode == TextureWrap::ClampToEdge) return std::clamp(i, 0, size - 1);
    const int r = i % size;
    return r < 0 ? r + size : r;
}

}  // namespace

glm::vec4 Sampler2D::fetch(int x, int y) const {
    if (x < 0 || y < 0 || x >= tex_->width || y >= tex_->height) return glm::vec4(0.0f);
    const size_t i = (size_t(y) * tex_->width + x) * 4;
    if (tex_->format == TextureFormat::RGBA8) {
        const uint8_t* t = &tex_->texels8[i];
        return glm::vec4(t[0], t[1], t[2], t[3]) * (1.0f / 255.0f);
    }
    const float* t = &tex_->texels32[i];
    return glm::vec4(t[0], t[1], t[2], t[3]);
}

glm::vec4 Sampler2D::sample(const glm::vec2& st) const {
    if (tex_->filter == TextureFilter::Nearest) return sample_nearest(st);
    return tex_->format == TextureFormat::RGBA8 ? sample_linear_unorm8(st) : sample_linear_float(st);
}

glm::vec4 Sampler2D::sample_nearest(const glm::vec2& st) const {
    const int x = wrap(int(std::floor(st.x * float(tex_->width))), tex_->width, tex_->wrap);
    const int y = wrap(int(std::floor(st.y * float(tex_->height))), tex_->height, tex_->wrap);
    return fetch(x, y);
}

glm::vec4 Sampler2D::sample_linear_float(const glm::vec2& st) const {
    const float u = st.x * float(tex_->width) - 0.5f, v = st.y * float(tex_->height) - 0.5f;
    const float fu = std::floor(u), fv = std::floor(v);
    const float a = u - fu, b = v - fv;
    const int x0 = int(fu), y0 = int(fv);
    const int xa = wrap(x0, tex_->width, tex_->wrap), xb = wrap(x0 + 1, tex_->width, tex_->wrap);
    const int ya = wrap(y0, tex_->height, tex_->wrap), yb = wrap(y0 + 1, tex_->height, tex_->wrap);
    const glm::vec4 t00 = fetch(xa, ya), t10 = fetch(xb, ya), t01 = fetch(xa, yb), t11 = fetch(xb, yb);
    glm::vec4 out;
    for (int c = 0; c < 4; ++c) {
        // lerp(t, p, q) = fma(t, q - p, p), measured exact on an FMA host.
        const float r0 = std::fma(a, t10[c] - t00[c], t00[c]);
        const float r1 = std::fma(a, t11[c] - t01[c], t01[c]);
        out[c] = std::fma(b, r1 - r0, r0);
    }
    return out;
}

glm::vec4 Sampler2D::sample_linear_unorm8(const glm::vec2& st) const {
    // Placeholder until the 8-bit fixed-point path is written: float filter.
    return sample_linear_float(st);
}

}  // namespace st
