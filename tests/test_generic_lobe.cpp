// The generic lobe path against the hand-reduced fast paths it stands beside
// (GGX, the rough glass and the Charlie sheen here), and its moment weights.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/fresnel.h"
#include "brdflut/generic_lobe.h"
#include "brdflut/ggx_lobe.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/glass_integrals.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/microfacet.h"
#include "brdflut/sheen.h"
#include "brdflut/sheen_integrals.h"

using namespace brdflut;

namespace {

// The Charlie sheen with Neubelt's visibility as a generic lobe: no peak
// (the lobe is a ring toward grazing directions), coordinates about the
// normal.
class CharlieLobe final : public GenericLobe {
public:
    explicit CharlieLobe(double alpha) : charlie_{alpha} {}
    double f(const Vec3& wo, const Vec3& wi) const override {
        if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
        const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
        const double cos_h = h.z / std::sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
        return charlie_.D(cos_h) * neubelt_visibility(wo.z, wi.z);
    }

private:
    Charlie charlie_;
};

// The hints of a GGX reflection lobe: its peak at the mirror direction.
LobeHints ggx_reflection_hints(const Vec3& wo, double alpha) { return microfacet_reflection_hints(wo, alpha); }

// The rough dielectric of ggx_glass (glass_integrals.h) as two lobes, each
// from its BSDF alone: wo on the near side of an interface of relative
// index eta (far over near), the exact dielectric Fresnel F (1 under total
// internal reflection), G2 of wo and |cos| of the other direction.
//
class GlassLobe : public GenericLobe {
public:
    GlassLobe(double alpha, double eta, Visibility vis) : ggx_{alpha}, eta_(eta), vis_(vis) {}

protected:
    Ggx ggx_;
    double eta_;
    Visibility vis_;
};

// Reflection: F(wo.h) D(h) G2 / (4 mu_o mu_i) over the upper hemisphere.
// From inside (eta < 1) F has its critical-angle kink at wo.h = sqrt(1 -
// eta^2), a cone about wo (wi.wo = 2 (wo.h)^2 - 1).
class GlassReflectionLobe final : public GlassLobe {
public:
    using GlassLobe::GlassLobe;
    double f(const Vec3& wo, const Vec3& wi) const override {
        if (!(wo.z > 0.0) || !(wi.z > 0.0)) return 0.0;
        const Vec3 h{wo.x + wi.x, wo.y + wi.y, wo.z + wi.z};
        const double c = dot(wo, h) / std::sqrt(dot(h, h));
        return fresnel_dielectric(c, eta_) * ggx_D_along(ggx_.alpha, h) * ggx_.G2(wo.z, wi.z, vis_) /
               (4.0 * wo.z * wi.z);
    }
    LobeHints hints(const Vec3& wo) const override {
        LobeHints h = ggx_reflection_hints(wo, ggx_.alpha);
        if (eta_ < 1.0) h.kink_cones.push_back({wo, std::acos(1.0 - 2.0 * eta_ * eta_)});
        return h;
    }
};

// Transmission (Walter et al. 2007, with the eta_o^2 factor that makes it
// the fraction of the energy that crosses): over the lower hemisphere,
//   (1 - F(c)) D(m) G2 c |wi.m| eta^2 / (mu_o |mu_i| (wo.m + eta wi.m)^2),
// m the microfacet normal that refracts wo into wi (along wo + eta wi,
// turned toward wo; c = wo.m > 0, wi.m < 0, m.z > 0). Its support: within
// the largest deviation acos(min(eta, 1 / eta)) of -wo, and where m is above
// the horizon (wi.z < -mu_o / eta from outside, wi.z > -mu_o / eta from
// inside). Peak: the refraction by m = z, of width alpha |1 - mu_o / (eta
// cos_t)| in the plane and cos_t across it; under total internal reflection
// at m = z, the horizon.
class GlassTransmissionLobe final : public GlassLobe {
public:
    using GlassLobe::GlassLobe;
    double f(const Vec3& wo, const Vec3& wi) const override {
        if (!(wo.z > 0.0) || !(wi.z < 0.0)) return 0.0;
        Vec3 m{wo.x + eta_ * wi.x, wo.y + eta_ * wi.y, wo.z + eta_ * wi.z};
        const double m2 = dot(m, m);  // (wo.m + eta wi.m)^2 for the unit m
        if (dot(wo, m) < 0.0) m = {-m.x, -m.y, -m.z};
        const double len = std::sqrt(m2);
        const double c = dot(wo, m) / len, cos_t = -dot(wi, m) / len;
        if (!(c > 0.0) || !(cos_t > 0.0) || !(m.z > 0.0)) return 0.0;
        return (1.0 - fresnel_dielectric(c, eta_)) * ggx_D_along(ggx_.alpha, m) * ggx_.G2(wo.z, -wi.z, vis_) * c *
               cos_t * eta_ * eta_ / (wo.z * -wi.z * m2);
    }
    LobeHints hints(const Vec3& wo) const override {
        LobeHints h;
        h.has_peak = true;
        const double ct2 = 1.0 - (1.0 - wo.z * wo.z) / (eta_ * eta_);
        if (ct2 > 0.0) {
            const double cos_t = std::sqrt(ct2);
            h.peak = {-wo.x / eta_, -wo.y / eta_, -cos_t};
            h.width = ggx_.alpha * std::abs(1.0 - wo.z / (eta_ * cos_t));
            h.aspect = std::min(1.0, cos_t + ggx_.alpha);
        } else {
            h.peak = {-1.0, 0.0, 0.0};
        }
        h.support.push_back({{-wo.x, -wo.y, -wo.z}, std::acos(std::min(eta_, 1.0 / eta_))});
        if (eta_ > 1.0)
            h.support.push_back({{0.0, 0.0, -1.0}, std::acos(wo.z / eta_)});
        else if (wo.z < eta_)
            h.support.push_back({{0.0, 0.0, 1.0}, std::acos(-wo.z / eta_)});
        return h;
    }
};

const Visibility kBoth[] = {Visibility::height_correlated, Visibility::separable};

}  // namespace

TEST(GenericLobe, AgreesWithTheHandReducedGgxPathWithinBothEstimates) {
    for (Visibility vis : kBoth)
        for (double alpha : {(0.5 / 128) * (0.5 / 128), 1e-3, 0.02, 0.2, 0.6, 1.0})
            for (double mu : {0.5 / 128, 0.05, 0.3, 0.7, 1.0}) {
                const GgxLobe lobe(alpha, vis);
                GenericOptions opt;
                opt.abs_tol = 1e-9;
                const Estimate<2> g = generic_moments<2>(lobe, mu, kSplitSumWeights, opt);
                const Estimate<2> r = ggx_split_sum(mu, alpha, vis, 1e-9);
                for (int c = 0; c < 2; ++c) {
                    EXPECT_NEAR(g.value[c], r.value[c], g.error[c] + r.error[c] + 1e-14)
                        << to_string(vis) << " alpha " << alpha << " mu " << mu << " channel " << c;
                    // Above the tolerance only by the rounding of the directions
                    // at the smallest alpha (generic_lobe.h).
                    EXPECT_LE(g.error[c], alpha > 1e-3 ? 1e-9 : 3e-9);
                }
            }
    // The average too.
    GenericOptions opt;
    opt.abs_tol = 1e-8;
    for (double alpha : {0.05, 0.5}) {
        const Estimate<1> g = generic_albedo_average(GgxLobe(alpha, Visibility::height_correlated), opt);
        const Estimate<1> r = ggx_albedo_average(alpha, Visibility::height_correlated, 1e-8);
        EXPECT_NEAR(g.value[0], r.value[0], g.error[0] + r.error[0] + 1e-14) << alpha;
    }
}

TEST(GenericLobe, LtcOfTheGenericKindIsTheFitOfTheGgxKind) {
    // The same GGX lobe fitted as LtcLobe's generic kind (f from GgxLobe,
    // norms from the generic path) and as its ggx kind (the hand-reduced
    // f and split sums): the norms agree within both estimates, f to
    // rounding, and the generic fit is a local minimum of the ggx kind's
    // objective by the criterion verify applies to every fitted texel.
    for (double alpha : {0.05, 0.3, 0.8})
        for (double mu : {0.2, 0.7, 1.0}) {
            SCOPED_TRACE("alpha " + std::to_string(alpha) + " mu " + std::to_string(mu));
            const LtcLobe fast(mu, alpha, Visibility::height_correlated);
            const LtcLobe generic(std::make_shared<const GgxLobe>(alpha), mu, alpha, 1, 1e-9);
            EXPECT_TRUE(generic.peaks_near_mirror());
            const LtcNorms a = ltc_norms(fast), b = ltc_norms(generic);
            EXPECT_NEAR(a.n0, b.n0, a.n0_error + b.n0_error + 1e-14);
            EXPECT_NEAR(a.n1, b.n1, a.n1_error + b.n1_error + 1e-14);
            for (double t : {-1.2, -0.7, -0.3, 0.0, 0.4, 1.1}) {
                const Vec3 wi{std::sin(t) * 0.8, 0.6 * std::sin(t), std::cos(t)};
                const double n = std::sqrt(dot(wi, wi));
                const Vec3 u{wi.x / n, wi.y / n, wi.z / n};
                EXPECT_NEAR(generic(u), fast(u), 1e-12 * fast(u) + 1e-300);
            }
            EXPECT_LE(ltc_local_minimum_drop(fast, fit_ltc(generic)), 1e-9);
        }
}

// E_R and E_T of ggx_glass against the two lobes, from outside (eta = 1.5)
// and from inside (eta = 1 / 1.5, total internal reflection below mu =
// 0.745), at low, moderate and full roughness and grazing to normal view:
// within the sum of the two error estimates, nothing added.
TEST(GenericLobe, AgreesWithTheHandReducedGlassPathWithinBothEstimates) {
    GenericOptions reflection;
    reflection.abs_tol = 1e-9;
    GenericOptions transmission = reflection;
    transmission.domain = LobeDomain::lower_hemisphere;
    for (Visibility vis : kBoth)
        for (double eta : {1.5, 1.0 / 1.5})
            for (double alpha : {0.05, 0.3, 1.0})
                for (double mu : {0.5 / 128, 0.3, 0.8, 1.0}) {
                    const Estimate<2> r = ggx_glass(mu, alpha, eta, vis, 1e-9);
                    const Estimate<1> gr = generic_albedo(GlassReflectionLobe(alpha, eta, vis), mu, reflection);
                    const Estimate<1> gt = generic_albedo(GlassTransmissionLobe(alpha, eta, vis), mu, transmission);
                    EXPECT_LE(std::abs(gr.value[0] - r.value[0]), gr.error[0] + r.error[0])
                        << "E_R " << to_string(vis) << " eta " << eta << " alpha " << alpha << " mu " << mu;
                    EXPECT_LE(std::abs(gt.value[0] - r.value[1]), gt.error[0] + r.error[1])
                        << "E_T " << to_string(vis) << " eta " << eta << " alpha " << alpha << " mu " << mu;
                }
    // The averages over mu at alpha = 0.3: both from outside, and from
    // inside E_T avg, which the fast path takes from outside by reciprocity
    // and the generic path integrates. (The inside E_R avg, with its
    // critical-angle kink in every E_R(mu), takes the generic path 3 s.)
    reflection.abs_tol = transmission.abs_tol = 1e-8;
    const double alpha = 0.3;
    const Visibility vis = Visibility::height_correlated;
    const Estimate<2> out = ggx_glass_average(alpha, 1.5, vis, 1e-8);
    const Estimate<1> gr = generic_albedo_average(GlassReflectionLobe(alpha, 1.5, vis), reflection);
    const Estimate<1> gt = generic_albedo_average(GlassTransmissionLobe(alpha, 1.5, vis), transmission);
    EXPECT_LE(std::abs(gr.value[0] - out.value[0]), gr.error[0] + out.error[0]);
    EXPECT_LE(std::abs(gt.value[0] - out.value[1]), gt.error[0] + out.error[1]);
    const Estimate<2> in = ggx_glass_average(alpha, 1.0 / 1.5, vis, 1e-8);
    const Estimate<1> gi = generic_albedo_average(GlassTransmissionLobe(alpha, 1.0 / 1.5, vis), transmission);
    EXPECT_LE(std::abs(gi.value[0] - in.value[1]), gi.error[0] + in.error[1]);
}

TEST(GenericLobe, AgreesWithTheHandReducedSheenPathWithinBothEstimates) {
    GenericOptions opt;
    opt.abs_tol = 1e-9;
    for (double alpha : {0.05, 0.3, 1.0})
        for (double mu : {0.5 / 128, 0.1, 0.5, 1.0}) {
            const Estimate<1> g = generic_albedo(CharlieLobe(alpha), mu, opt);
            const Estimate<1> s = sheen_charlie_albedo(mu, alpha);
            EXPECT_NEAR(g.value[0], s.value[0], g.error[0] + s.error[0] + 1e-14) << "alpha " << alpha << " mu " << mu;
        }
}

TEST(GenericLobe, MomentWeightsAreTheFresnelFactorsTheyName) {
    const GgxLobe lobe(0.3);
    GenericOptions opt;
    opt.abs_tol = 1e-11;
    for (double mu : {0.1, 0.6}) {
        using namespace moment_weight;
        const std::array<MomentWeight, 4> w = {MomentWeight{one}, MomentWeight{schlick},
                                               MomentWeight{schlick_power, 5.0}, MomentWeight{one_minus_schlick}};
        const Estimate<4> m = generic_moments<4>(lobe, mu, w, opt);
        // (1 - c)^p at p = 5 is Schlick's factor, node for node.
        EXPECT_EQ(m.value[1], m.value[2]) << mu;
        // 1 = (1 - (1 - c)^5) + (1 - c)^5, within the estimates.
        EXPECT_NEAR(m.value[0], m.value[1] + m.value[3], m.error[0] + m.error[1] + m.error[3] + 1e-15) << mu;
        // The split sums of the hand-reduced GGX path.
        const Estimate<2> ab = ggx_split_sum(mu, 0.3, Visibility::height_correlated, 1e-11);
        EXPECT_NEAR(m.value[3], ab.value[0], m.error[3] + ab.error[0] + 1e-14) << mu;
        EXPECT_NEAR(m.value[1], ab.value[1], m.error[1] + ab.error[1] + 1e-14) << mu;
    }
    // Weights that depend on their parameter: the exact dielectric Fresnel
    // (0 at eta = 1, Schlick-like at eta = 1.5) and F82's c (1 - c)^6, each
    // against the Monte Carlo route with the same weight.
    const std::array<MomentWeight, 3> w = {MomentWeight{moment_weight::dielectric_fresnel, 1.0},
                                           MomentWeight{moment_weight::dielectric_fresnel, 1.5},
                                           MomentWeight{moment_weight::f82}};
    const Estimate<3> q = generic_moments<3>(lobe, 0.4, w, opt);
    EXPECT_EQ(q.value[0], 0.0);
    const Estimate<3> mc = generic_moments_mc<3>(lobe, 0.4, w, 200000, 11);
    for (std::size_t k = 1; k < 3; ++k)
        EXPECT_NEAR(q.value[k], mc.value[k], 4.0 * mc.error[k] + q.error[k]) << "weight " << k;
    EXPECT_GT(q.value[1], 0.03);  // about F0 = 0.04 at moderate view
    EXPECT_LT(q.value[1], 0.2);
}

TEST(GenericLobe, WeightCuspsAndClampsAreConesAboutTheView) {
    // (1 - c)^p is a cusp at wi = wo unless p is an integer: cones at eight
    // scales; none for Schlick's p = 5 or for a smooth p = 8.5.
    EXPECT_EQ(weight_view_cones({moment_weight::schlick_power, 1.25}).size(), 8u);
    EXPECT_EQ(weight_view_cones({moment_weight::schlick_power, 0.3}).size(), 8u);
    EXPECT_TRUE(weight_view_cones({moment_weight::schlick_power, 5.0}).empty());
    EXPECT_TRUE(weight_view_cones({moment_weight::schlick_power, 8.5}).empty());
    // Total internal reflection at eta = 0.7: F = 1 below c = sqrt(1 - eta^2),
    // a cone of half angle 2 acos(c) about wo.
    const std::vector<double> tir = weight_view_cones({moment_weight::dielectric_fresnel, 0.7});
    ASSERT_EQ(tir.size(), 1u);
    EXPECT_NEAR(std::cos(0.5 * tir[0]), std::sqrt(1.0 - 0.49), 1e-14);
    // The remapped dielectric is clamped at 0 where F dips below F0: not at
    // eta = 1.5 or 3, from c* to 1 at eta = 4.5556 (F(c*) = F0 there).
    EXPECT_TRUE(weight_view_cones({moment_weight::dielectric_remapped, 1.5}).empty());
    EXPECT_TRUE(weight_view_cones({moment_weight::dielectric_remapped, 3.0}).empty());
    const double eta = 4.5556;
    const std::vector<double> dip = weight_view_cones({moment_weight::dielectric_remapped, eta});
    ASSERT_EQ(dip.size(), 1u);
    const double c_star = std::cos(0.5 * dip[0]), f0 = std::pow((eta - 1.0) / (eta + 1.0), 2.0);
    EXPECT_NEAR(fresnel_dielectric(c_star, eta), f0, 1e-14);
    EXPECT_GT(c_star, 0.1);
    EXPECT_LT(c_star, 0.3);
    EXPECT_LT(fresnel_dielectric(0.5 * (c_star + 1.0), eta), f0);
}

TEST(GenericLobe, ErrorEstimatesCoverWeightCuspsAndClamps) {
    // Cycles' generalized Schlick s at texels where the estimates once fell
    // short of the true error (by up to 8 times) because the weight's cusp
    // (p = 1.25) or clamp (eta = 4.5556) lay inside a ring: the estimate at
    // the tables' tolerance, 1e-8, must cover the difference to a run at 1e-13.
    struct Case {
        MomentWeight w;
        double alpha, mu;
    };
    for (const Case& c : {Case{{moment_weight::schlick_power, 1.25}, 0.751111, 0.733333},
                          Case{{moment_weight::schlick_power, 1.25}, 0.751111, 0.133333},
                          Case{{moment_weight::dielectric_remapped, 4.55556}, 0.537778, 0.0666667}}) {
        const GgxLobe lobe(c.alpha, Visibility::height_correlated, GgxLobeKind::vndf);
        GenericOptions opt, tight;
        opt.abs_tol = 1e-8;
        tight.abs_tol = 1e-13;
        tight.max_intervals = 4000;
        const Estimate<1> e = generic_moments<1>(lobe, c.mu, {c.w}, opt);
        const Estimate<1> r = generic_moments<1>(lobe, c.mu, {c.w}, tight);
        EXPECT_LE(std::abs(e.value[0] - r.value[0]), e.error[0] + r.error[0]) << c.w.p << " " << c.alpha << " " << c.mu;
        EXPECT_LT(e.error[0], 1e-8);
    }
}

namespace {

// f = gamma^q, gamma the angle between wi and the unit d (in the x-z
// plane): a point cusp at d for q = 1.3, declared or not.
class ConeCuspLobe final : public GenericLobe {
public:
    ConeCuspLobe(Vec3 d, bool declared) : d_(d), declared_(declared) {}
    double f(const Vec3&, const Vec3& wi) const override {
        return std::pow(std::acos(std::clamp(dot(wi, d_), -1.0, 1.0)), kQ);
    }
    LobeHints hints(const Vec3&) const override {
        LobeHints h;
        if (declared_) h.point_kinks = {d_};
        return h;
    }
    static constexpr double kQ = 1.3;

private:
    Vec3 d_;
    bool declared_;
};

// 2 pi times the integral of gamma^q sin(gamma) (cos(gamma) too over the
// hemisphere about d) over gamma in [0, end], in gamma^(1/2) to flatten the
// cusp.
double cusp_reference(double end, bool cosine) {
    AdaptiveOptions opt;
    opt.abs_tol = 1e-14;
    opt.max_intervals = 2000;
    const Estimate<1> e = integrate_adaptive<1>(
        [&](double t) {
            const double g = t * t;
            return std::array<double, 1>{std::pow(g, ConeCuspLobe::kQ) * std::sin(g) * (cosine ? std::cos(g) : 1.0) *
                                         2.0 * t};
        },
        0.0, std::sqrt(end), opt);
    return kTwoPi * e.value[0];
}

}  // namespace

TEST(GenericLobe, PointKinksAreCutAboutAndCostFewerEvaluations) {
    // The centre of the rings (the normal, for a lobe without a peak) over
    // the hemisphere, taken in theta flattened at the centre; and a point off
    // the centre over the sphere, the rings near it cut about it. Each within
    // its estimate of the closed reference, and cheaper declared than not.
    struct Case {
        Vec3 d;
        LobeDomain domain;
        double reference;
    };
    const double s = std::sqrt(1.0 - 0.36);
    for (const Case& c : {Case{{0.0, 0.0, 1.0}, LobeDomain::hemisphere, cusp_reference(0.5 * kPi, true)},
                          Case{{0.6, 0.0, s}, LobeDomain::sphere, cusp_reference(kPi, false)}}) {
        GenericOptions opt;
        opt.domain = c.domain;
        const Estimate<1> on = generic_moments<1>(ConeCuspLobe(c.d, true), 0.5, {kWeightOne}, opt);
        const Estimate<1> off = generic_moments<1>(ConeCuspLobe(c.d, false), 0.5, {kWeightOne}, opt);
        EXPECT_LE(std::abs(on.value[0] - c.reference), on.error[0] + 1e-12) << c.d.x;
        EXPECT_LT(std::abs(on.value[0] - c.reference), 1e-8) << c.d.x;
        EXPECT_LT(on.evaluations, off.evaluations) << c.d.x;
    }
}
