// image_library.h: what shadertwin asks of OpenImageIO (reading image
// files of any format it knows; and, as the reference the faster paths are
// checked against, the SHA-1 pixel hash golden files keep and a
// comparison's error statistics), behind one interface. Its implementation
// (image_library_oiio.cpp) is a shared library of ours,
// libshadertwin_oiio.so, loaded the first time a process reads an image:
// OpenImageIO brings some 260 shared libraries, whose loading takes 0.37 s
// of a process. Writing PNG and EXR, the pixel hash and the error
// statistics therefore do without it (png_file.h, exr_file.h, pixel_hash.h,
// error_stats.h; image_files_test.cpp holds them to this interface's
// results), so a render or a compare never loads it. Nothing else links
// OpenImageIO.
//
// The module is looked for, in order: SHADERTWIN_IMAGE_LIBRARY (a path);
// ../lib beside the running executable (an installed bin/shadertwin); the
// build tree it was built in; and by name on the executable's run path
// (a user's tool, linked with the install's lib folder on it). Not found:
// a runtime_error with one line naming the places tried.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace st {

struct ImageErrorStats {
    double max_error = 0, mean_error = 0, rms_error = 0, psnr = 0;
};

class ImageLibrary {
public:
    virtual ~ImageLibrary() = default;

    // Reads any image the library reads, refusing (before allocating) a
    // header beyond max_side pixels a side or 64 channels; RGBA floats out,
    // as stored (a PNG's colour not multiplied by its alpha),
    // missing alpha 1, the string attributes named "shadertwin:*", and what
    // the file held: "file:pixel_type" (OpenImageIO's name: uint8, uint16,
    // half, float, ...), "file:channels" and "file:colour_space" (its
    // oiio:ColorSpace, often empty).
    // False when it cannot, with the library's words in `error` (which may
    // be empty: a decoder may have said it on stderr instead).
    virtual bool read(const std::string& path, int max_side, int& width, int& height, std::vector<float>& rgba,
                      std::map<std::string, std::string>& attributes, std::string& error) const = 0;
    // OpenImageIO's computePixelHashSHA1 of a float RGBA image.
    virtual std::string pixel_hash(const float* rgba, int width, int height) const = 0;
    // ImageBufAlgo::compare of two float RGBA images of one size.
    virtual ImageErrorStats error_stats(const float* a, const float* b, int width, int height) const = 0;
};

// The library, loaded on the first call (thread-safe); throws runtime_error
// when the module cannot be loaded.
const ImageLibrary& image_library();

// Bumped whenever ImageLibrary changes: a module of another version is refused.
inline constexpr int kImageLibraryVersion = 3;

}  // namespace st

// The module's one entry point.
extern "C" const st::ImageLibrary* shadertwin_image_library(int version);
