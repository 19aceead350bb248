// interp_frag.cpp: twin of glsl/interp.frag, line for line.
#include "kernels/triangles/interp.h"

namespace st {

namespace {
constexpr int v_colour = 0;  // layout(location = 0) in vec4 v_colour
}  // namespace

Vec4 InterpFragment::main(const Fragment& frag) const {
    return frag.varying(v_colour);
}

}  // namespace st
