// image_io.h: EXR and PNG files through OpenImageIO, written atomically.
//
// Every writer renders to a temporary name beside the target and renames it
// into place, so an error never leaves a half-written file.
#pragma once

#include <map>
#include <string>

#include "image/image.h"

namespace st {

using Metadata = std::map<std::string, std::string>;

// Float RGBA EXR with the metadata as string attributes, after the
// process's provenance (file_provenance.h; `metadata` wins on a clash).
void write_exr(const std::string& path, const Image& image, const Metadata& metadata);
// 8-bit RGBA PNG holding to_unorm8() of each channel, as is. PNGs carry the
// process's provenance as text chunks (file_provenance.h).
void write_png(const std::string& path, const Image& image);
// An 8-bit RGB(A) PNG from bytes already converted (heat maps).
void write_png_bytes(const std::string& path, int width, int height, int channels,
                     const unsigned char* bytes);
// read_image refuses a file whose header claims more than this on a side
// (the largest scene is 8192 a side), before allocating for it.
inline constexpr int kMaxImageSide = 8192;
// What an image file held before read_image made float RGBA of it.
struct ImageFileFormat {
    std::string pixel_type;    // OpenImageIO's: "uint8", "uint16", "half", "float", ...
    int channels = 4;          // 1 grey, 2 grey and alpha, 3 RGB, 4 RGBA, or more
    std::string colour_space;  // as the file (or its format) says; often empty
    bool integer_pixels() const { return pixel_type.rfind("uint", 0) == 0 || pixel_type.rfind("int", 0) == 0; }
};

// Reads any image OpenImageIO reads as float RGBA (missing channels 0,
// missing alpha 1), rows top to bottom, the values as stored (colour not
// multiplied by alpha); integer pixels are scaled to [0, 1].
// Throws std::runtime_error with one line on failure.
Image read_image(const std::string& path, Metadata* metadata = nullptr, ImageFileFormat* format = nullptr);

// Writes text through a temporary file and rename, with the process's
// provenance line in the file's syntax (file_provenance.h).
void write_text_file(const std::string& path, const std::string& text);
// The same for a file this process copies rather than makes: recorded as
// "copied by", after any record the text already holds.
void write_copied_text_file(const std::string& path, const std::string& text);

}  // namespace st
