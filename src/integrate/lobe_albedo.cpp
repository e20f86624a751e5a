// Directional and average albedo of the Disney and Oren-Nayar lobes: the
// dispatch to each lobe's quadrature, the average over mu, and the
// independent Monte Carlo estimator.
#include "brdflut/lobe_integrals.h"

#include <cmath>

#include "brdflut/disney.h"
#include "brdflut/oren_nayar.h"
#include "brdflut/random.h"
#include "integrate/lobe_albedo_detail.h"

namespace brdflut {

std::string_view to_string(Lobe lobe) {
    switch (lobe) {
        case Lobe::disney_diffuse: return "disney_diffuse";
        case Lobe::disney_subsurface: return "disney_subsurface";
        case Lobe::disney_sheen: return "disney_sheen";
        case Lobe::disney_clearcoat: return "disney_clearcoat";
        case Lobe::oren_nayar: return "oren_nayar";
        case Lobe::fujii_oren_nayar: return "fujii_oren_nayar";
        case Lobe::eon: return "eon";
    }
    return "unknown";
}

Estimate<1> lobe_albedo(Lobe lobe, double mu_o, double p, double abs_tol) {
    switch (lobe) {
        case Lobe::disney_diffuse: return detail::disney_diffuse_albedo(mu_o, p, abs_tol);
        case Lobe::disney_subsurface: return detail::disney_subsurface_albedo(mu_o, p, abs_tol);
        case Lobe::disney_sheen: return detail::disney_sheen_albedo(mu_o, abs_tol);
        case Lobe::disney_clearcoat: return detail::disney_clearcoat_albedo(mu_o, p, abs_tol);
        case Lobe::oren_nayar: return detail::oren_nayar_albedo(mu_o, p, abs_tol);
        case Lobe::fujii_oren_nayar: return detail::fujii_oren_nayar_albedo(mu_o, p, abs_tol);
        case Lobe::eon: return detail::eon_albedo(mu_o, p, abs_tol);
    }
    return {};
}

Estimate<1> lobe_albedo_average(Lobe lobe, double p, double abs_tol) {
    // The clearcoat's average is one integral over the half vector and wo,
    // much cheaper than nesting its two-dimensional albedo integral.
    if (lobe == Lobe::disney_clearcoat) return detail::disney_clearcoat_albedo_average(p, abs_tol);
    // 2 * integral of E(mu) mu dmu = integral over theta in [0, pi/2] of
    // E(cos(theta)) sin(2 theta) dtheta: in theta the square-root behaviour of
    // the Oren-Nayar albedos at mu = 1 is smooth. The range is broken at
    // mu = 1/4, 1/16, 1/64, where the clearcoat's masking and Fresnel change
    // fast; the clearcoat no longer comes here, but the breaks cost the other
    // lobes little and removing them would change their stored tables.
    const double breaks[] = {0.0, std::acos(0.25), std::acos(1.0 / 16), std::acos(1.0 / 64),
                             0.5 * kPi};
    AdaptiveOptions opt;
    opt.abs_tol = 0.125 * abs_tol;
    opt.controlled = 1;
    Estimate<1> out;
    for (int k = 0; k < 4; ++k) {
        const Estimate<2> e = integrate_adaptive<2>(
            [&](double theta) -> std::array<double, 2> {
                const Estimate<1> in = lobe_albedo(lobe, std::cos(theta), p, 0.25 * abs_tol);
                const double w = std::sin(2.0 * theta);
                return {w * in.value[0], w * in.error[0]};
            },
            breaks[k], breaks[k + 1], opt);
        out.value[0] += e.value[0];
        out.error[0] += e.error[0] + e.value[1];
        out.evaluations += e.evaluations;
    }
    return out;
}

double lobe_brdf(Lobe lobe, const Vec3& wo, const Vec3& wi, double p) {
    switch (lobe) {
        case Lobe::disney_diffuse: return disney_diffuse_brdf(wo, wi, p);
        case Lobe::disney_subsurface: return disney_subsurface_brdf(wo, wi, p);
        case Lobe::disney_sheen: return disney_sheen_brdf(wo, wi);
        case Lobe::disney_clearcoat: return disney_clearcoat_brdf(wo, wi, p);
        case Lobe::oren_nayar: return OrenNayar{p}.brdf(wo, wi);
        case Lobe::fujii_oren_nayar: return FujiiOrenNayar{p}.brdf(wo, wi);
        case Lobe::eon: return Eon{FujiiOrenNayar{p}}.brdf(wo, wi);
    }
    return 0.0;
}

namespace {

// f(wo, wi) cos(theta_i) / pdf(wi) for one sampled wi. Cosine-weighted
// hemisphere sampling (pdf = mu_i / pi), except the clearcoat: GTR1 half
// vectors, cos^2(theta_h) = (1 - a^(2(1 - u1)))/(1 - a^2) (Burley 2012,
// appendix B), pdf(wi) = D cos(theta_h) / (4 wo.h).
double lobe_sample(Lobe lobe, const Vec3& wo, double p, Rng& rng) {
    const double u1 = rng.uniform(), u2 = rng.uniform();
    const double phi = kTwoPi * u2;
    if (lobe == Lobe::disney_clearcoat) {
        const double a2 = sqr(clearcoat_alpha(p));
        const double cos_h = std::sqrt((1.0 - std::pow(a2, 1.0 - u1)) / (1.0 - a2));
        const double sin_h = safe_sqrt(1.0 - cos_h * cos_h);
        const Vec3 h{sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h};
        const double o_h = dot(wo, h);
        const Vec3 wi{2.0 * o_h * h.x - wo.x, 2.0 * o_h * h.y - wo.y, 2.0 * o_h * h.z - wo.z};
        if (wi.z <= 0.0 || o_h <= 0.0 || cos_h <= 0.0) return 0.0;
        const double pdf = gtr1_D(cos_h, clearcoat_alpha(p)) * cos_h / (4.0 * o_h);
        return disney_clearcoat_brdf(wo, wi, p) * wi.z / pdf;
    }
    // 1 - u1 > 0 keeps wi strictly above the horizon.
    const double r = std::sqrt(u1);
    const Vec3 wi{r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - u1)};
    return kPi * lobe_brdf(lobe, wo, wi, p);
}

}  // namespace

Estimate<1> lobe_albedo_mc(Lobe lobe, double mu_o, double p, long long samples,
                           std::uint64_t seed) {
    const Vec3 wo = direction_from_mu(clamp01(mu_o));
    Rng rng(seed, 0);
    MeanAccumulator<1> acc;
    for (long long s = 0; s < samples; ++s) {
        const double w = lobe_sample(lobe, wo, p, rng);
        acc.add(&w);
    }
    return acc.estimate();
}

Estimate<1> lobe_albedo_average_mc(Lobe lobe, double p, long long samples, std::uint64_t seed) {
    Rng rng(seed, 1);
    MeanAccumulator<1> acc;
    for (long long s = 0; s < samples; ++s) {
        // mu with density 2 mu on [0, 1]: mu = sqrt(u); 1 - u keeps mu > 0.
        const double mu = std::sqrt(1.0 - rng.uniform());
        const double w = lobe_sample(lobe, direction_from_mu(mu), p, rng);
        acc.add(&w);
    }
    return acc.estimate();
}

}  // namespace brdflut
