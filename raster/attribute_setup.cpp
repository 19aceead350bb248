// attribute_setup.cpp: llvmpipe's coefficient setup (lp_state_setup.c,
// init_args and calc_coef4), operation for operation. Nothing here is fused:
// the setup code is built from separate LLVM fmul/fsub instructions.
#include "raster/attribute_setup.h"

namespace st {

void setup_attribute_planes(const SetupVertex& v0, const SetupVertex& v1, const SetupVertex& v2,
                            int varying_count, const Interpolations& interpolation, std::vector<Plane>& planes) {
    // Pixel index (0, 0) is centred at window (0.5, 0.5).
    const float x0_center = v0.pos.x - 0.5f, y0_center = v0.pos.y - 0.5f;
    const float dx01 = v0.pos.x - v1.pos.x, dy01 = v0.pos.y - v1.pos.y;
    const float dx20 = v2.pos.x - v0.pos.x, dy20 = v2.pos.y - v0.pos.y;
    const float e = dx01 * dy20, f = dy01 * dx20;
    const float ooa = 1.0f / (e - f);
    const float dx20_ooa = dx20 * ooa, dy20_ooa = dy20 * ooa;
    const float dx01_ooa = dx01 * ooa, dy01_ooa = dy01 * ooa;

    auto plane = [&](float a0, float a1, float a2) {
        const float da01 = a0 - a1, da20 = a2 - a0;
        Plane p;
        p.dadx = da01 * dy20_ooa - da20 * dy01_ooa;
        p.dady = da20 * dx01_ooa - da01 * dx20_ooa;
        const float at_v0 = p.dadx * x0_center + p.dady * y0_center;
        p.a0 = a0 - at_v0;
        planes.push_back(p);
    };
    plane(v0.pos.z, v1.pos.z, v2.pos.z);
    plane(v0.pos.inv_w, v1.pos.inv_w, v2.pos.inv_w);
    for (int slot = 0; slot < varying_count; ++slot)
        for (int c = 0; c < 4; ++c) {
            const float a0 = v0.varyings[slot][c], a1 = v1.varyings[slot][c], a2 = v2.varyings[slot][c];
            switch (interpolation[size_t(slot)]) {
                case Interpolation::Smooth:  // premultiplied by 1/w per vertex
                    plane(a0 * v0.pos.inv_w, a1 * v1.pos.inv_w, a2 * v2.pos.inv_w);
                    break;
                case Interpolation::NoPerspective:
                    plane(a0, a1, a2);
                    break;
                case Interpolation::Flat:  // the provoking vertex's bits, copied
                    planes.push_back(Plane{a2, 0.0f, 0.0f});
                    break;
            }
        }
}

}  // namespace st
