// frame.cpp: transformations of a whole Frame that both backends share.
#include "frame/frame.h"

namespace st {

Frame coverage_frame(const Frame& frame) {
    Frame out = frame;
    for (Pass& pass : out.passes) {
        pass.clear_colour = glm::vec4(0.0f);
        for (DrawCall& draw : pass.draws) {
            draw.fragment = "coverage";
            draw.state = DrawState{};
            // Counts, exact in the float targets (to 2^24 fragments a pixel).
            draw.state.blend = BlendMode::Factors;
            draw.state.factors = BlendFactors{BlendFactor::One, BlendFactor::One, BlendFactor::One, BlendFactor::One};
        }
    }
    return out;
}

}  // namespace st
