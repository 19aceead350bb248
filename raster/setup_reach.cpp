// setup_reach.cpp: see setup_reach.h. The same steps as Binner::set_up,
// without varyings: trivial reject on the outcodes, the fused viewport
// transform for unclipped vertices, the clipper for the rest.
#include "raster/setup_reach.h"

#include <vector>

#include "raster/clipper.h"
#include "raster/fixed_point.h"
#include "raster/float_env.h"

namespace st {

std::optional<WindowPos> first_unsnappable_position(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                                    const Viewport& viewport) {
    const FlushDenormals float_env;  // as the vertex stage and the binner run
    const glm::vec4* clip[3] = {&a, &b, &c};
    unsigned mask_or = 0, mask_and = ~0u;
    ClipVertex v[3];
    for (int k = 0; k < 3; ++k) {
        const unsigned m = clip_mask(*clip[k]);
        mask_or |= m;
        mask_and &= m;
        v[k].out.position = *clip[k];
        v[k].window = to_window(*clip[k], viewport);
    }
    if (mask_and) return std::nullopt;  // outside one plane: dropped whole
    auto unsnappable = [](const WindowPos& w) { return !snappable(w.x) || !snappable(w.y); };
    if (!mask_or) {
        for (const ClipVertex& k : v)
            if (unsnappable(k.window)) return k.window;
        return std::nullopt;
    }
    std::vector<ClipVertex> clipped;
    clip_triangle(v[0], v[1], v[2], mask_or, 0, Interpolations{}, viewport, clipped);
    for (const ClipVertex& k : clipped)
        if (unsnappable(k.window)) return k.window;
    return std::nullopt;
}

}  // namespace st
