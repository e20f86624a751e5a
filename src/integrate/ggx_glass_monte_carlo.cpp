// Monte Carlo estimates of the GGX dielectric albedos, independent of the
// quadrature in ggx_glass.cpp: a visible normal m (Heitz 2018, density
// G1(wo) (wo.m) D(m) / mu_o) per sample, and both channels from it,
//   E_R += F(wo.m) G2(wo, wr) / G1(wo)   when the reflection wr is above the horizon,
//   E_T += (1 - F(wo.m)) G2(wo, wt) / G1(wo)   when the refraction wt is below it,
// with the directions built as vectors (not from the thresholds the
// quadrature splits at).
#include <cmath>

#include "brdflut/fresnel.h"
#include "brdflut/glass_integrals.h"
#include "brdflut/random.h"

namespace brdflut {
namespace {

constexpr double kGrazingMu = 1e-16;

void sample(const Ggx& g, Visibility vis, double eta, const Vec3& wo, double u1, double u2, double* w) {
    w[0] = w[1] = 0.0;
    const Vec3 m = g.sample_visible_normal(wo, u1, u2);
    const double c = dot(wo, m);
    if (!(c > 0.0)) return;
    const double g1 = g.G1(wo.z);
    const double F = fresnel_dielectric(std::min(c, 1.0), eta);
    // Reflection wr = 2 c m - wo.
    const double mu_r = 2.0 * c * m.z - wo.z;
    if (mu_r > 0.0) w[0] = F * g.G2(wo.z, mu_r, vis) / g1;
    // Refraction wt = -wo / eta + (c / eta - cos_t) m.
    const double ct2 = 1.0 - (1.0 - c * c) / (eta * eta);
    if (ct2 > 0.0 && F < 1.0) {
        const double b = c / eta - std::sqrt(ct2);
        const Vec3 wt{-wo.x / eta + b * m.x, -wo.y / eta + b * m.y, -wo.z / eta + b * m.z};
        if (wt.z < 0.0) w[1] = (1.0 - F) * g.G2(wo.z, -wt.z, vis) / g1;
    }
}

Estimate<2> smooth(double mu, double eta) {
    Estimate<2> out;
    const double F = fresnel_dielectric(std::min(mu, 1.0), eta);
    out.value = {F, 1.0 - F};
    return out;
}

}  // namespace

Estimate<2> ggx_glass_mc(double mu_o, double alpha, double eta, Visibility vis, long long samples,
                         std::uint64_t seed) {
    if (!(mu_o >= 0.0) || !(eta > 0.0)) return {};
    mu_o = std::clamp(mu_o, kGrazingMu, 1.0);
    if (!(alpha > 0.0)) return smooth(mu_o, eta);  // a delta lobe: nothing to sample
    const Ggx g{alpha};
    const Vec3 wo = direction_from_mu(mu_o);
    Rng rng(seed, 0);
    MeanAccumulator<2> acc;
    for (long long s = 0; s < samples; ++s) {
        const double u1 = rng.uniform(), u2 = rng.uniform();
        double w[2];
        sample(g, vis, eta, wo, u1, u2, w);
        acc.add(w);
    }
    return acc.estimate();
}

Estimate<2> ggx_glass_average_mc(double alpha, double eta, Visibility vis, long long samples,
                                 std::uint64_t seed) {
    if (!(eta > 0.0)) return {};
    const Ggx g{alpha};
    Rng rng(seed, 1);
    MeanAccumulator<2> acc;
    for (long long s = 0; s < samples; ++s) {
        // mu with density 2 mu on [0, 1]: mu = sqrt(u); 1 - u keeps mu > 0.
        const double mu = std::sqrt(1.0 - rng.uniform());
        const double u1 = rng.uniform(), u2 = rng.uniform();
        double w[2];
        if (alpha > 0.0) {
            sample(g, vis, eta, direction_from_mu(mu), u1, u2, w);
        } else {
            const Estimate<2> e = smooth(mu, eta);
            w[0] = e.value[0];
            w[1] = e.value[1];
        }
        acc.add(w);
    }
    return acc.estimate();
}

}  // namespace brdflut
