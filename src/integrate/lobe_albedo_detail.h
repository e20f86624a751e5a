// Quadrature of each lobe's directional albedo (src/integrate/*_albedo.cpp),
// dispatched by lobe_albedo() in lobe_albedo.cpp.
#pragma once

#include "brdflut/quadrature.h"

namespace brdflut::detail {

Estimate<1> disney_diffuse_albedo(double mu_o, double roughness, double abs_tol);
Estimate<1> disney_subsurface_albedo(double mu_o, double roughness, double abs_tol);
Estimate<1> disney_sheen_albedo(double mu_o, double abs_tol);
Estimate<1> disney_clearcoat_albedo(double mu_o, double gloss, double abs_tol);
// E_avg directly, as one integral over the half vector and wo.
Estimate<1> disney_clearcoat_albedo_average(double gloss, double abs_tol);
Estimate<1> oren_nayar_albedo(double mu_o, double sigma, double abs_tol);
Estimate<1> fujii_oren_nayar_albedo(double mu_o, double sigma, double abs_tol);
Estimate<1> eon_albedo(double mu_o, double sigma, double abs_tol);

// A polynomial integrand integrated exactly by Gauss-Legendre: the error is the
// difference of two rules that are both exact for its degree (rounding only).
template <class F>
Estimate<1> exact_polynomial_integral(F&& f, double a, double b, int degree) {
    const int n = degree / 2 + 1;
    const double v = integrate_gauss<1>(f, a, b, n + 2)[0];
    const double w = integrate_gauss<1>(f, a, b, n + 1)[0];
    Estimate<1> e;
    e.value[0] = v;
    e.error[0] = std::abs(v - w) + 1e-15 * (std::abs(v) + 1e-300);
    e.evaluations = 2 * n + 3;
    return e;
}

}  // namespace brdflut::detail
