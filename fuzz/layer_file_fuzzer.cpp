// layer_file_fuzzer.cpp: `slab --layers` / `profile --layers` files through
// read_layer_file. Refusals: fuzz_support.h.
#include "fuzz/fuzz_support.h"
#include "scene/layer_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = st::fuzz::write_input(data, size, ".json");
    st::fuzz::expect_accept_or_refuse([&] {
        if (st::read_layer_file(path).empty()) std::abort();  // an accepted file has a layer
    });
    return 0;
}
