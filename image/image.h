// image.h: the float RGBA image both backends produce, rows top to bottom.
// Float images are the truth; 8-bit values derive from them (unorm8.h).
#pragma once

#include <string>
#include <vector>

namespace st {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgba;  // width * height * 4, row 0 = top of the picture

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(size_t(w) * h * 4, 0.0f) {}
    float* pixel(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const float* pixel(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// OpenImageIO's computePixelHashSHA1 of the RGBA float image, rows top to
// bottom: the `hash` that render prints and golden files keep.
std::string pixel_hash(const Image& image);

}  // namespace st
