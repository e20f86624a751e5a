// Monte Carlo estimates of the GGX split-sum integrals, independent of the
// quadrature in ggx_split_sum.cpp.
//
// Half vectors come from a defensive mixture (Hesterberg 1995, "Weighted
// average importance sampling and defensive mixture distributions"): with
// probability 1/2 a visible normal of the BRDF's own alpha (Heitz 2018),
// otherwise a normal from D cos(theta_h) of a wide distribution,
// alpha' = max(alpha, 0.5). The first keeps the variance low; the second
// makes steep microfacets, whose reflection leaves the hemisphere, common
// enough to be counted: for small alpha the energy they carry (~alpha^2) is
// otherwise an event too rare for any affordable sample count to see, and
// the sample variance would hide it.
#include <cmath>

#include "brdflut/ggx_integrals.h"
#include "brdflut/random.h"

namespace brdflut {
namespace {

constexpr double kWideAlpha = 0.5;

// Density of the half vector m under the mixture (per solid angle of m).
double mixture_pdf(const Ggx& ggx, const Ggx& wide, const Vec3& wo, const Vec3& m) {
    const double o_m = dot(wo, m);
    const double visible = o_m > 0.0 ? ggx.G1(wo.z) * o_m * ggx.D(m.z) / wo.z : 0.0;
    return 0.5 * visible + 0.5 * wide.D(m.z) * m.z;
}

// A normal from D cos(theta_m): tan^2(theta_m) = alpha^2 xi / (1 - xi).
Vec3 sample_normal(const Ggx& g, double u1, double u2) {
    const double t2 = g.alpha * g.alpha * u1 / (1.0 - u1);
    const double cos_t = 1.0 / std::sqrt(1.0 + t2);
    const double sin_t = std::sqrt(t2) * cos_t;
    const double phi = kTwoPi * u2;
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
}

// One sample: estimator weights {A, B} of f cos(theta_i) / pdf(wi), with
// f cos(theta_i) / pdf(wi) = D G2 (wo.m) / (mu_o pdf(m)) (dw_i = 4 (wo.m) dw_m).
void split_sum_sample(const Ggx& ggx, const Ggx& wide, Visibility vis, const Vec3& wo, Rng& rng, double* w) {
    const double pick = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    const Vec3 m = pick < 0.5 ? ggx.sample_visible_normal(wo, u1, u2) : sample_normal(wide, u1, u2);
    w[0] = w[1] = 0.0;
    const double o_m = dot(wo, m);
    const double mu_i = 2.0 * o_m * m.z - wo.z;
    if (mu_i <= 0.0 || o_m <= 0.0) return;
    const double pdf = mixture_pdf(ggx, wide, wo, m);
    if (!(pdf > 0.0)) return;
    const double weight = ggx.D(m.z) * ggx.G2(wo.z, mu_i, vis) * o_m / (wo.z * pdf);
    const double fc = schlick_weight(o_m);
    w[0] = weight * (1.0 - fc);
    w[1] = weight * fc;
}

}  // namespace

Estimate<2> ggx_split_sum_mc(double mu_o, double alpha, Visibility vis, long long samples, std::uint64_t seed) {
    Estimate<2> out;
    if (!(mu_o > 0.0)) return out;
    if (!(alpha > 0.0)) {  // mirror: a delta lobe, nothing to sample
        const double fc = schlick_weight(std::min(mu_o, 1.0));
        out.value = {1.0 - fc, fc};
        return out;
    }
    const Ggx ggx{alpha}, wide{std::max(alpha, kWideAlpha)};
    const Vec3 wo = direction_from_mu(std::min(mu_o, 1.0));
    Rng rng(seed, 0);
    MeanAccumulator<2> acc;
    for (long long s = 0; s < samples; ++s) {
        double w[2];
        split_sum_sample(ggx, wide, vis, wo, rng, w);
        acc.add(w);
    }
    for (int c = 0; c < 2; ++c) {
        out.value[c] = acc.mean[c];
        out.error[c] = acc.standard_error(c);
    }
    out.evaluations = static_cast<int>(std::min<long long>(samples, 1 << 30));
    return out;
}

Estimate<1> ggx_albedo_average_mc(double alpha, Visibility vis, long long samples, std::uint64_t seed) {
    Estimate<1> out;
    if (!(alpha > 0.0)) {
        out.value[0] = 1.0;
        return out;
    }
    const Ggx ggx{alpha}, wide{std::max(alpha, kWideAlpha)};
    Rng rng(seed, 1);
    MeanAccumulator<1> acc;
    for (long long s = 0; s < samples; ++s) {
        // mu with density 2 mu on [0, 1]: mu = sqrt(u); 1 - u keeps mu > 0.
        const double mu = std::sqrt(1.0 - rng.uniform());
        double w[2];
        split_sum_sample(ggx, wide, vis, direction_from_mu(mu), rng, w);
        const double e = w[0] + w[1];
        acc.add(&e);
    }
    out.value[0] = acc.mean[0];
    out.error[0] = acc.standard_error(0);
    out.evaluations = static_cast<int>(std::min<long long>(samples, 1 << 30));
    return out;
}

}  // namespace brdflut
