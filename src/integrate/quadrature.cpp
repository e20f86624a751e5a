#include "brdflut/quadrature.h"

#include <cmath>
#include <map>
#include <mutex>

#include "brdflut/math.h"

namespace brdflut {

const GaussLegendre& gauss_legendre(int n) {
    static std::mutex mutex;
    static std::map<int, GaussLegendre> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(n);
    if (it != cache.end()) return it->second;
    GaussLegendre rule;
    rule.x.resize(static_cast<std::size_t>(n));
    rule.w.resize(static_cast<std::size_t>(n));
    // Newton iteration on P_n from the Chebyshev-like initial guess.
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double dp = 0.0;
        for (int iter = 0; iter < 100; ++iter) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            if (n == 1) p0 = 1.0;
            const double pn = n == 0 ? 1.0 : p1;
            dp = n * (x * pn - p0) / (x * x - 1.0);
            const double dx = pn / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        // Recompute the derivative at the converged node.
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
            const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
            p0 = p1;
            p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1.0);
        const double w = 2.0 / ((1.0 - x * x) * dp * dp);
        rule.x[static_cast<std::size_t>(i)] = -x;
        rule.x[static_cast<std::size_t>(n - 1 - i)] = x;
        rule.w[static_cast<std::size_t>(i)] = w;
        rule.w[static_cast<std::size_t>(n - 1 - i)] = w;
    }
    return cache.emplace(n, std::move(rule)).first->second;
}

}  // namespace brdflut
