// image.cpp: hashing of float images.
#include "image/image.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace st {

std::string pixel_hash(const Image& image) {
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    // Wrap without copying; rows are already top to bottom.
    OIIO::ImageBuf buf(spec, const_cast<float*>(image.rgba.data()));
    return OIIO::ImageBufAlgo::computePixelHashSHA1(buf);
}

}  // namespace st
