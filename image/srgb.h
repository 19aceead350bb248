// srgb.h: the sRGB transfer function (IEC 61966-2-1), the one place it is
// computed. A texture file in sRGB (a PNG as painted) is decoded with it
// to linear values on load (scene/texture_files.cpp), as an asset pipeline
// does; both backends then sample the same linear texels.
#pragma once

namespace st {

// An encoded value in [0, 1] to linear, in double: c / 12.92 up to
// 0.04045, ((c + 0.055) / 1.055)^2.4 above. Values outside [0, 1] are
// clamped first; NaN gives 0.
double srgb_to_linear(double encoded);

}  // namespace st
