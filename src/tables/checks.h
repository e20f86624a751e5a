// Helpers for the independent checks the table families declare
// (TableDefinition::checks): the largest error of a table's evaluator over a
// list of points against an expected value, and the closed forms several
// families share.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "brdflut/catalogue.h"
#include "brdflut/math.h"
#include "brdflut/microfacet.h"
#include "brdflut/quadrature.h"

namespace brdflut::tables {

using CheckResult = std::pair<double, std::string>;

// "at (a, b)" for a point's coordinates, named by the table's axes when given.
template <std::size_t N>
std::string point_text(const std::array<double, N>& p) {
    std::ostringstream s;
    s.precision(6);
    for (std::size_t i = 0; i < N; ++i) s << (i ? ", " : "") << p[i];
    return "at (" + s.str() + ")";
}

// Largest |evaluate(p)[channel] - expected(p)| over the points (a non-finite
// difference is the worst).
template <std::size_t N, class Expected>
CheckResult worst_over(const TexelEvaluator& e, const std::vector<std::array<double, N>>& points, int channel,
                       Expected expected) {
    CheckResult r{0.0, ""};
    for (const auto& p : points) {
        const TexelValue v = e.evaluate(p.data(), 0);
        const double err = std::abs(v.value[static_cast<std::size_t>(channel)] - expected(p));
        if (!std::isfinite(err)) return {HUGE_VAL, point_text(p) + ": not finite"};
        if (err > r.first || r.second.empty()) r = {err, point_text(p)};
    }
    return r;
}

// Largest error(value of the texel, p) over the points, as worst_over, for
// checks that combine channels.
template <std::size_t N, class Error>
CheckResult worst_error(const TexelEvaluator& e, const std::vector<std::array<double, N>>& points, Error error) {
    CheckResult r{0.0, ""};
    for (const auto& p : points) {
        const double err = std::abs(error(e.evaluate(p.data(), 0), p));
        if (!std::isfinite(err)) return {HUGE_VAL, point_text(p) + ": not finite"};
        if (err > r.first || r.second.empty()) r = {err, point_text(p)};
    }
    return r;
}

// Every combination of the values of two lists, as points (x, y).
inline std::vector<std::array<double, 2>> grid_points(const std::vector<double>& xs, const std::vector<double>& ys) {
    std::vector<std::array<double, 2>> out;
    for (double x : xs)
        for (double y : ys) out.push_back({x, y});
    return out;
}
inline std::vector<std::array<double, 1>> points_1d(const std::vector<double>& xs) {
    std::vector<std::array<double, 1>> out;
    for (double x : xs) out.push_back({x});
    return out;
}

// GGX at alpha = 1 with the height-correlated G2: D = 1/pi and
// f = 1 / (2 pi (mu_o + mu_i)), so E(mu) = 1 - mu ln(1 + 1/mu) and
// E_avg = (4/3)(1 - ln 2).
inline double ggx_albedo_alpha_one(double mu) { return 1.0 - mu * std::log1p(1.0 / mu); }
inline double ggx_albedo_avg_alpha_one() { return 4.0 / 3.0 * (1.0 - std::log(2.0)); }

// GGX at alpha = 1 with the Schlick-Smith G1 mu / (mu (1 - k) + k), k = 1/2:
// E(mu) = G1(mu)/(2 mu) integral of G1(mu_i) dmu_i = 2 (1 - ln 2) / (1 + mu).
inline double ggx_schlick_albedo_alpha_one(double mu) { return 2.0 * (1.0 - std::log(2.0)) / (1.0 + mu); }

// Charlie sheen with Neubelt's visibility, n = 2 + 1/alpha:
// E(1) = 2^(1 - n/2) / (n + 2) (wo = n, mu_i = cos(2 theta_h)), and
// E(0) = (n / pi)(sqrt(pi)/2) Gamma((n + 1)/2) / Gamma(n/2 + 1).
inline double charlie_albedo_normal(double alpha) {
    const double n = 2.0 + 1.0 / alpha;
    return std::pow(2.0, 1.0 - 0.5 * n) / (n + 2.0);
}
inline double charlie_albedo_grazing(double alpha) {
    const double n = 2.0 + 1.0 / alpha;
    return n / kPi * 0.5 * std::sqrt(kPi) * std::exp(std::lgamma(0.5 * (n + 1.0)) - std::lgamma(0.5 * n + 1.0));
}

// GGX rough glass without an interface (eta = 1): no reflection, and the
// transmission is the straight path masked on both sides,
// E_T(mu) = G2(mu, mu) (1 + Lambda(mu)).
inline double glass_index_matched_transmission(double mu, double alpha, Visibility vis) {
    const Ggx g{alpha};
    return g.G2(mu, mu, vis) * (1.0 + g.lambda(mu));
}
// Its average 2 * integral of E_T(mu) mu dmu, by adaptive quadrature of
// that closed form in ln(mu) panels (E_T turns on the scale of alpha).
double glass_index_matched_transmission_average(double alpha, Visibility vis);

}  // namespace brdflut::tables
