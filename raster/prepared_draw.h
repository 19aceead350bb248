// prepared_draw.h: one draw call as the CPU pipeline holds it between
// frames: its twins (bound to the draw's uniforms and samplers), this
// frame's vertices and the vertex stage's output.
#pragma once

#include <deque>
#include <memory>
#include <vector>

#include "frame/frame.h"
#include "raster/viewport.h"
#include "shading/program.h"
#include "texture/sampler2d.h"
#include "texture/sampler_cube.h"

namespace st {

struct PreparedDraw {
    const DrawCall* call = nullptr;
    VertexArray vertices;                 // this frame's vertices (the host stage writes here)
    std::unique_ptr<VertexTwin> vertex;
    std::unique_ptr<FragmentTwin> fragment;
    std::deque<Sampler2D> samplers;       // deque: Bindings keeps pointers
    std::deque<SamplerCube> cube_samplers;
    // Textures that are render targets: their texels are what earlier passes
    // drew, copied in before this draw's pass (sampler points at its entry
    // of `samplers`, refreshed then).
    struct TargetTexture {
        Texture texture;
        Sampler2D* sampler = nullptr;
    };
    std::deque<TargetTexture> target_textures;
    Bindings bindings;
    int varying_count = 0;
    uint32_t inputs_read = ~0u;           // fragment->inputs_read()
    Interpolations interpolation{};       // fragment->interpolations()
    std::vector<VertexOut> shaded;        // vertex stage output, per vertex
    std::vector<WindowPos> window;        // viewport transform of `shaded`
    std::vector<unsigned> clip_masks;     // outcodes of `shaded`
};

}  // namespace st
