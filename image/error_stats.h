// error_stats.h: the error statistics `compare` and `diff` print (largest,
// mean and RMS absolute difference, PSNR), computed here rather than by
// loading OpenImageIO (0.37 s a process) for ImageBufAlgo::compare, with
// the same arithmetic, so the numbers are the ones it gave
// (image_files_test.cpp checks them against the module).
#pragma once

#include "image/image_library.h"

namespace st {

// Over every channel of two float RGBA images of one size: the absolute
// difference of each value in float, summed in double per batch of 4096
// pixels and the batches summed; PSNR against the largest magnitude seen
// (at least 1). Where either value is not finite and the two are not alike
// (both NaN, or both infinite), the largest error becomes infinite, and
// such a value after that joins the sums.
ImageErrorStats error_stats(const float* a, const float* b, int width, int height);

}  // namespace st
