// png_file.h: writing an 8-bit PNG with libpng, as every compare and render
// does several times a scene. Not through OpenImageIO: loading its 260
// shared libraries took 0.37 s of each process that wrote an image, more
// than most scenes' render (image_library.h keeps it for reading).
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace st {

// Writes width x height pixels of `channels` bytes each (1 grey, 2 grey and
// alpha, 3 RGB, 4 RGBA; rows top to bottom) to `path`, each attribute as a
// tEXt chunk (OpenImageIO reads them back as attributes of those names), at
// zlib's fastest level (an 800x600 PNG in 61 ms instead of 293, for 17 %
// more bytes). Returns the error, empty when it wrote the file.
std::string write_png_file(const std::string& path, int width, int height, int channels, const uint8_t* pixels,
                           const std::map<std::string, std::string>& attributes);

}  // namespace st
