// thin_slab_sweep_scene.cpp: the "thin-slab-sweep" kind. One pixel per
// sample of thin_slab_sweep_rows(): the inputs go in an RGBA32F texture read
// with texelFetch, and glsl/thin_slab/thin_slab_sweep.frag writes the model's outputs,
// so both backends evaluate exactly the same inputs.
#include "scene/input_error.h"
#include "scene/scene_kinds.h"
#include "scene/thin_slab_sweep.h"

namespace st {

Frame build_thin_slab_sweep_scene(JsonReader&, SceneSize size) {
    const auto rows = thin_slab_sweep_rows(size.width);
    if (size.height != int(rows.size()))
        throw InputError("field 'height' must be " + std::to_string(rows.size()) + " (one row per sweep)");
    Texture inputs;
    inputs.sampler = "inputs";
    inputs.format = TextureFormat::RGBA32F;
    inputs.set_filter(TextureFilter::Nearest);
    inputs.set_wrap(TextureWrap::ClampToEdge);
    inputs.width = size.width;
    inputs.height = size.height;
    for (const SweepRow& row : rows)  // texture row 0 = window row 0 (bottom)
        for (const SweepSample& s : row.samples)
            for (float v : {s.tau1, s.mu, s.mu0, 0.0f}) inputs.texels32.push_back(v);

    DrawCall draw;
    draw.vertex = "background";
    draw.fragment = "thin_slab_sweep";
    draw.vertices.attribute_count = 2;
    for (const glm::vec4& v : {glm::vec4(-1, -1, 0, 1), glm::vec4(0, 0, 0, 1), glm::vec4(3, -1, 0, 1),
                               glm::vec4(2, 0, 0, 1), glm::vec4(-1, 3, 0, 1), glm::vec4(0, 2, 0, 1)})
        draw.vertices.data.push_back(v);
    draw.indices = {0, 1, 2};
    draw.textures.push_back(std::move(inputs));

    Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    pass.draws.push_back(std::move(draw));
    Frame frame;
    frame.passes.push_back(std::move(pass));
    return frame;
}

}  // namespace st
