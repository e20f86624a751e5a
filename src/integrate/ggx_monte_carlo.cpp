// Monte Carlo estimates of the GGX split-sum integrals, independent of the
// quadrature in ggx_split_sum.cpp.
//
// Half vectors come from two strata combined with the balance heuristic
// (Veach and Guibas 1995, "Optimally Combining Sampling Techniques"): 3/4 of
// the samples are visible normals of the BRDF's own alpha (Heitz 2018), 1/4
// are normals from D cos(theta_h) of a wide distribution, alpha' =
// max(alpha, 0.5). Each sample x counts f(x) / (c1 p1(x) + c2 p2(x)), c_j the
// stratum's share of the samples. Where the visible normals carry the
// integral this is as good as sampling them alone; the wide stratum makes
// steep microfacets, whose reflection leaves the hemisphere, common enough to
// be counted: for small alpha the energy they carry (~alpha^2) is otherwise an
// event too rare for any affordable sample count to see, and the sample
// variance would hide it.
#include <cmath>

#include "brdflut/ggx_integrals.h"
#include "brdflut/random.h"

namespace brdflut {
namespace {

constexpr double kWideAlpha = 0.5;

// A normal from D cos(theta_m): tan^2(theta_m) = alpha^2 xi / (1 - xi).
Vec3 sample_normal(const Ggx& g, double u1, double u2) {
    const double t2 = g.alpha * g.alpha * u1 / (1.0 - u1);
    const double cos_t = 1.0 / std::sqrt(1.0 + t2);
    const double sin_t = std::sqrt(t2) * cos_t;
    const double phi = kTwoPi * u2;
    return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
}

struct Sampler {
    Ggx ggx, wide;
    Visibility vis;
    long long n_visible, n_wide;  // samples per stratum

    Sampler(double alpha, Visibility v, long long samples)
        : ggx{alpha}, wide{std::max(alpha, kWideAlpha)}, vis(v), n_visible(samples - samples / 4),
          n_wide(samples / 4) {}

    // Sample s (stratum by index): weights {A, B} of f cos(theta_i) over the
    // combined density, f cos(theta_i) dw_i = D G2 (wo.m) / mu_o dw_m.
    void sample(long long s, const Vec3& wo, Rng& rng, double* w) const {
        const double u1 = rng.uniform(), u2 = rng.uniform();
        const Vec3 m = s < n_visible ? ggx.sample_visible_normal(wo, u1, u2) : sample_normal(wide, u1, u2);
        w[0] = w[1] = 0.0;
        const double o_m = dot(wo, m);
        const double mu_i = 2.0 * o_m * m.z - wo.z;
        if (mu_i <= 0.0 || o_m <= 0.0) return;
        const double n = static_cast<double>(n_visible + n_wide);
        const double p_visible = ggx.G1(wo.z) * o_m * ggx.D(m.z) / wo.z;
        const double p_wide = wide.D(m.z) * m.z;
        const double pdf = (static_cast<double>(n_visible) * p_visible + static_cast<double>(n_wide) * p_wide) / n;
        if (!(pdf > 0.0)) return;
        const double weight = ggx.D(m.z) * ggx.G2(wo.z, mu_i, vis) * o_m / (wo.z * pdf);
        const double fc = schlick_weight(o_m);
        w[0] = weight * (1.0 - fc);
        w[1] = weight * fc;
    }
};

// Mean over all samples and its standard error from the two independent
// strata: Var = (N1 s1^2 + N2 s2^2) / N^2.
template <int N>
Estimate<N> combine(const MeanAccumulator<N>& a, const MeanAccumulator<N>& b) {
    Estimate<N> out;
    const double n = static_cast<double>(a.n + b.n);
    for (int c = 0; c < N; ++c) {
        out.value[c] = (static_cast<double>(a.n) * a.mean[c] + static_cast<double>(b.n) * b.mean[c]) / n;
        auto var = [c](const MeanAccumulator<N>& m) {
            return m.n > 1 ? m.m2[c] / static_cast<double>(m.n - 1) : (m.n == 1 ? HUGE_VAL : 0.0);
        };
        out.error[c] = std::sqrt(static_cast<double>(a.n) * var(a) + static_cast<double>(b.n) * var(b)) / n;
    }
    out.evaluations = static_cast<int>(std::min<double>(n, 1 << 30));
    return out;
}

}  // namespace

Estimate<2> ggx_split_sum_mc(double mu_o, double alpha, Visibility vis, long long samples, std::uint64_t seed) {
    Estimate<2> out;
    if (!(mu_o >= 0.0)) return out;
    mu_o = std::max(mu_o, kGrazingMu);  // the grazing limit
    if (!(alpha > 0.0)) {  // mirror: a delta lobe, nothing to sample
        const double fc = schlick_weight(std::min(mu_o, 1.0));
        out.value = {1.0 - fc, fc};
        return out;
    }
    const Sampler sampler(alpha, vis, samples);
    const Vec3 wo = direction_from_mu(std::min(mu_o, 1.0));
    Rng rng(seed, 0);
    MeanAccumulator<2> visible, wide;
    for (long long s = 0; s < samples; ++s) {
        double w[2];
        sampler.sample(s, wo, rng, w);
        (s < sampler.n_visible ? visible : wide).add(w);
    }
    return combine(visible, wide);
}

Estimate<1> ggx_albedo_average_mc(double alpha, Visibility vis, long long samples, std::uint64_t seed) {
    if (!(alpha > 0.0)) {
        Estimate<1> out;
        out.value[0] = 1.0;
        return out;
    }
    const Sampler sampler(alpha, vis, samples);
    Rng rng(seed, 1);
    MeanAccumulator<1> visible, wide;
    for (long long s = 0; s < samples; ++s) {
        // mu with density 2 mu on [0, 1]: mu = sqrt(u); 1 - u keeps mu > 0.
        const double mu = std::sqrt(1.0 - rng.uniform());
        double w[2];
        sampler.sample(s, direction_from_mu(mu), rng, w);
        const double e = w[0] + w[1];
        (s < sampler.n_visible ? visible : wide).add(&e);
    }
    return combine(visible, wide);
}

}  // namespace brdflut
