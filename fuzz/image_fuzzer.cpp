// image_fuzzer.cpp: images through read_image (height maps, `diff`). The
// first byte picks the file's extension, the rest is the file; accepted
// images must be within the stated size. Refusals: fuzz_support.h.
#include "fuzz/fuzz_support.h"
#include "image/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    static const char* const kExtensions[] = {".png", ".exr", ".hdr", ".tif"};
    const std::string path = st::fuzz::write_input(data + 1, size - 1, kExtensions[data[0] % 4]);
    st::fuzz::expect_accept_or_refuse([&] {
        const st::Image image = st::read_image(path);
        if (image.width < 1 || image.height < 1 || image.width > st::kMaxImageSide || image.height > st::kMaxImageSide)
            std::abort();
    });
    return 0;
}
