// float_env.h: the floating-point environment llvmpipe renders in.
//
// llvmpipe's rasterizer threads and its draw (vertex) path run with
// flush-to-zero and denormals-are-zero set (lp_rast.c, draw_pt.c), so a
// denormal input or result counts as 0 there. The CPU pipeline runs in the
// same environment; FlushDenormals sets it for a scope on the calling thread.
#pragma once

#include <xmmintrin.h>

namespace st {

class FlushDenormals {
public:
    FlushDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kFtz | kDaz); }
    ~FlushDenormals() { _mm_setcsr(saved_); }
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;

private:
    static constexpr unsigned kFtz = 0x8000, kDaz = 0x0040;
    unsigned saved_;
};

}  // namespace st
