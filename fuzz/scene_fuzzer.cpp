// scene_fuzzer.cpp: a scene file and --set overrides, through load_scene as
// `render` calls it. An input is the scene's JSON text, then optionally a
// line "--set" and one override assignment per line after it.
// Refusals: fuzz_support.h.
#include <string>
#include <vector>

#include "fuzz/fuzz_support.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const size_t split = text.find("\n--set\n");
    std::vector<std::string> overrides;
    if (split != std::string::npos) {
        size_t at = split + 7;
        while (at <= text.size() && overrides.size() < 16) {
            size_t end = text.find('\n', at);
            if (end == std::string::npos) end = text.size();
            overrides.push_back(text.substr(at, end - at));
            at = end + 1;
        }
    }
    const std::string document = text.substr(0, split);
    const std::string path = st::fuzz::write_input(reinterpret_cast<const uint8_t*>(document.data()),
                                                   document.size(), ".json");
    st::fuzz::expect_accept_or_refuse([&] { const st::Scene scene = st::load_scene(path, overrides); });
    return 0;
}
