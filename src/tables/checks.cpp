#include "tables/checks.h"

namespace brdflut::tables {

double glass_index_matched_transmission_average(double alpha, Visibility vis) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-14;
    opt.max_intervals = 2000;
    opt.rule = KronrodRule::k31;
    // 2 * integral over mu of E_T(mu) mu, taken in y = ln(mu) as
    // 2 * integral of E_T(e^y) e^(2y) dy from ln(1e-16), below which the
    // integrand (at most e^(2y)) adds less than 1e-32.
    auto f = [&](double y) {
        const double mu = std::exp(y);
        return std::array<double, 1>{2.0 * glass_index_matched_transmission(mu, alpha, vis) * mu * mu};
    };
    return integrate_adaptive_panels<1>(f, std::log(1e-16), 0.0, 16, opt).value[0];
}

}  // namespace brdflut::tables
