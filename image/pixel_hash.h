// pixel_hash.h: the SHA-1 pixel hash golden files keep, computed with
// nettle rather than by loading OpenImageIO (0.37 s a process).
#pragma once

#include <string>

namespace st {

// SHA-1 of the float RGBA pixels' bytes, rows top to bottom, as 40
// upper-case hex digits: what OpenImageIO's computePixelHashSHA1 gives for
// the same buffer (image_files_test.cpp checks it against the module).
std::string sha1_pixel_hash(const float* rgba, int width, int height);

}  // namespace st
