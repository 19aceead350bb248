// png_structure.h: a PNG file's chunks walked before libpng reads it, so
// that a truncated file is refused by us. (OpenImageIO 2.4's PNG reader
// leaks its error message when libpng's read runs past the end of the file:
// it longjmps over a std::string. LeakSanitizer finds that leak, and it is
// not ours to suppress.)
#pragma once

#include <string>

namespace st {

// Empty when the file is not a PNG, or is one whose chunks are all whole up
// to IEND; otherwise why not ("truncated in chunk IDAT", ...).
std::string png_structure_error(const std::string& path);

}  // namespace st
