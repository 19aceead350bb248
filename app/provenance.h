// provenance.h: what produced an image: versions, renderer and CPU flags.
// Goes into every EXR's metadata and into `shadertwin --version`.
#pragma once

#include <string>

namespace st {

std::string shadertwin_version();
// The CPU feature flags that change llvmpipe's arithmetic (sse4.1, avx, avx2,
// fma, f16c, avx512f), space-separated, from /proc/cpuinfo.
std::string cpu_flags();
// "22.3.6" out of GL_VERSION "4.5 (Core Profile) Mesa 22.3.6"; "" if absent.
std::string mesa_version(const std::string& gl_version);
// "15.0.6" out of GL_RENDERER "llvmpipe (LLVM 15.0.6, 256 bits)"; "" if absent.
std::string llvm_version(const std::string& gl_renderer);

}  // namespace st
