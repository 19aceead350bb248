// srgb.h: the sRGB transfer function (IEC 61966-2-1), the one place it is
// computed on the host. A texture file in sRGB (a PNG as painted) is
// decoded with it to linear values on load (scene/texture_files.cpp), as an
// asset pipeline does, and an SRGB8_ALPHA8 texture's mip levels are
// filtered in linear and encoded back with it (texture/mip_generation.cpp).
// (What llvmpipe's sampler decodes per texel is another curve:
// texture/srgb_decode.h.)
#pragma once

namespace st {

// An encoded value in [0, 1] to linear, in double: c / 12.92 up to
// 0.04045, ((c + 0.055) / 1.055)^2.4 above. Values outside [0, 1] are
// clamped first; NaN gives 0.
double srgb_to_linear(double encoded);
// Its inverse: linear in [0, 1] (clamped; NaN gives 0) to the encoded value.
double linear_to_srgb(double linear);

}  // namespace st
