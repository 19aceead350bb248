// plane.h: an attribute's plane equation over the screen, and the one place
// where the rasterizer evaluates it.
//
// The value at pixel index (px, py), i.e. at window position
// (px + 0.5, py + 0.5), is a0 + dadx * px + dady * py, evaluated as
// llvmpipe's fragment code does (lp_bld_interp.c, attribs_update_simple):
// two multiply-adds, x first, each fused on an FMA host. How a0, dadx and
// dady are built is in attribute_setup.cpp.
#pragma once

#include <cmath>

namespace st {

struct Plane {
    float a0 = 0, dadx = 0, dady = 0;

    float at(int px, int py) const {
        return std::fma(dady, float(py), std::fma(dadx, float(px), a0));
    }
};

}  // namespace st
