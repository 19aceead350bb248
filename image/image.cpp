// image.cpp: hashing of float images.
#include "image/image.h"

#include "image/image_library.h"

namespace st {

std::string pixel_hash(const Image& image) {
    return image_library().pixel_hash(image.rgba.data(), image.width, image.height);
}

}  // namespace st
