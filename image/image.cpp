// image.cpp: hashing of float images.
#include "image/image.h"

#include "image/pixel_hash.h"

namespace st {

std::string pixel_hash(const Image& image) {
    return sha1_pixel_hash(image.rgba.data(), image.width, image.height);
}

}  // namespace st
