// plane.h: an attribute's plane equation over the screen, and the one place
// where the rasterizer evaluates it.
//
// The value at pixel index (px, py), i.e. at window position
// (px + 0.5, py + 0.5), is a0 + dadx * px + dady * py. How a0, dadx and dady
// are built is in attribute_setup.cpp; both follow llvmpipe's arithmetic.
#pragma once

namespace st {

struct Plane {
    float a0 = 0, dadx = 0, dady = 0;

    float at(int px, int py) const { return a0 + dadx * float(px) + dady * float(py); }
};

}  // namespace st
