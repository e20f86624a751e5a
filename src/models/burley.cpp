#include "brdflut/burley.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "brdflut/error.h"
#include "brdflut/math.h"

namespace brdflut {

double burley_profile(double x) { return (std::exp(-x) + std::exp(-x / 3.0)) / (8.0 * kPi * x); }

double burley_radial_density(double x) { return 0.25 * (std::exp(-x) + std::exp(-x / 3.0)); }

double burley_cdf(double x) {
    if (std::isinf(x)) return 1.0;
    return -0.25 * std::expm1(-x) - 0.75 * std::expm1(-x / 3.0);
}

double burley_cdf_complement(double x) { return 0.25 * std::exp(-x) + 0.75 * std::exp(-x / 3.0); }

double burley_inverse_cdf(double u, double* error) {
    if (!(u >= 0.0 && u <= 1.0)) {
        std::ostringstream s;
        s.precision(10);
        s << "probability " << u << " is out of range; allowed: 0 <= u <= 1";
        throw Error(s.str());
    }
    if (error) *error = 0.0;
    if (u == 0.0) return 0.0;
    if (u == 1.0) return std::numeric_limits<double>::infinity();
    // y = e^(-x/3) solves y^3 + 3 y - 4 (1 - u) = 0.
    const double y = 2.0 * std::sinh(std::asinh(2.0 * (1.0 - u)) / 3.0);
    double x = -3.0 * std::log(y);
    // Newton on CDF(x) - u, whose derivative is the radial density. Near
    // u = 0 the starting x has lost relative precision (y is near 1); near
    // u = 1 the complement carries the precision instead.
    auto residual = [&](double v) {
        return u < 0.5 ? burley_cdf(v) - u : (1.0 - u) - burley_cdf_complement(v);
    };
    for (int it = 0; it < 2; ++it) x = std::max(0.0, x - residual(x) / burley_radial_density(x));
    if (error) {
        constexpr double eps = std::numeric_limits<double>::epsilon();
        // The last step's size, which the next would shrink quadratically,
        // plus the rounding of the residual (a few ulps of u or of 1 - u).
        *error = std::abs(residual(x) / burley_radial_density(x)) +
                 8.0 * eps * (std::min(u, 1.0 - u) / burley_radial_density(x) + x);
    }
    return x;
}

std::string_view to_string(BurleyScaling s) {
    switch (s) {
        case BurleyScaling::searchlight: return "searchlight";
        case BurleyScaling::diffuse_transmission: return "diffuse_transmission";
        case BurleyScaling::dmfp: return "dmfp";
    }
    return "?";
}

BurleyScaling burley_scaling_from_string(std::string_view s) {
    if (s == "searchlight") return BurleyScaling::searchlight;
    if (s == "diffuse_transmission") return BurleyScaling::diffuse_transmission;
    if (s == "dmfp") return BurleyScaling::dmfp;
    throw Error("--scaling '" + std::string(s) + "' is not known; allowed: searchlight, diffuse_transmission, dmfp");
}

double burley_scaling(double A, BurleyScaling s) {
    switch (s) {
        case BurleyScaling::searchlight: return 1.85 - A + 7.0 * std::pow(std::abs(A - 0.8), 3);
        case BurleyScaling::diffuse_transmission: return 1.9 - A + 3.5 * sqr(A - 0.8);
        case BurleyScaling::dmfp: return 3.5 + 100.0 * sqr(sqr(A - 0.33));
    }
    return 0.0;
}

double burley_transmission(double t, double A, BurleyScaling s) {
    return A * burley_cdf_complement(t * burley_scaling(A, s));
}

}  // namespace brdflut
