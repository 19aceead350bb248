// thin_slab_brackets.h: the brackets of Frisvad et al.'s Eq. 4 and 5 in
// double precision, written stably (expm1, no series): the yardstick the
// thin-slab shader's float forms are measured against (`sweep thin-slab`)
// and what the exact fragment twin evaluates (app/quality/thin_slab_exact.h).
#pragma once

#include <cmath>

namespace st::reference {

// Eq. 4 without E(0) Lambda / (4 pi): mu0 / (mu + mu0) (1 - e^(-tau1 (1/mu + 1/mu0))).
inline double frontlit_bracket(double tau1, double mu, double mu0) {
    return mu0 / (mu + mu0) * -std::expm1(-tau1 * (1.0 / mu + 1.0 / mu0));
}

// Eq. 5 without E(0) Lambda / (4 pi): mu0 / (mu - mu0) (e^(-tau1/mu) - e^(-tau1/mu0)),
// as e^(-tau1/mu0) expm1(tau1 (mu - mu0) / (mu mu0)), and its limit at mu = mu0.
inline double backlit_bracket(double tau1, double mu, double mu0) {
    if (mu == mu0) return tau1 / mu0 * std::exp(-tau1 / mu0);
    return mu0 / (mu - mu0) * std::exp(-tau1 / mu0) * std::expm1(tau1 * (mu - mu0) / (mu * mu0));
}

}  // namespace st::reference
