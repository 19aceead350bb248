// exr_file.h: writing a float RGBA OpenEXR file with the OpenEXR library
// itself (as png_file.h writes PNGs: without loading OpenImageIO).
#pragma once

#include <map>
#include <string>

namespace st {

// Writes width x height RGBA float pixels (rows top to bottom) to `path`,
// ZIP-compressed (OpenImageIO's default, which these files had before), each
// attribute as a string attribute of the header. Returns the error, empty
// when it wrote the file.
std::string write_exr_file(const std::string& path, int width, int height, const float* rgba,
                           const std::map<std::string, std::string>& attributes);

}  // namespace st
