// diffuse_fresnel.cpp: see diffuse_fresnel.h.
#include "optics/diffuse_fresnel.h"

namespace st::optics {

double diffuse_fresnel_reflectance(double eta) {
    if (eta < 1.0) return -0.4399 + 0.7099 / eta - 0.3319 / (eta * eta) + 0.0636 / (eta * eta * eta);
    return -1.4399 / (eta * eta) + 0.7099 / eta + 0.6681 + 0.0636 * eta;
}

double boundary_factor(double eta) {
    const double fdr = diffuse_fresnel_reflectance(eta);
    return (1.0 + fdr) / (1.0 - fdr);
}

}  // namespace st::optics
