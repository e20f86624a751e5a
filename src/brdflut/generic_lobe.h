// Directional moments of any isotropic reflection lobe, from its BRDF alone.
//
// A lobe is declared by f(wo, wi) (cosine not included) and, optionally, by
// hints on its shape: the direction where it peaks (the mirror direction of
// a glossy lobe), its angular width there, how much narrower it is across
// the plane of the peak and the normal, and the cones and points where f
// has a kink. From that alone this file computes, with no numerics specific
// to the lobe:
//
//   M_k(mu_o) = integral over wi.z > 0 of f(wo, wi) w_k(wo.h) cos(theta_i) dw_i
//
// for weights w_k of c = wo.h (h the half vector of wo and wi), for example
// 1, (1 - c)^5 and 1 - (1 - c)^5 (the split sums); the directional albedo
// (weight 1); its average E_avg = 2 * integral of E(mu) mu dmu; and Monte
// Carlo estimates of the same, by the lobe's own sampler or by cosine-weighted
// sampling.
//
// Quadrature. wi is written in polar coordinates (theta, psi) about the peak
// p: wi = cos(theta) p + sin(theta) (cos(psi) e1 + sin(psi) e2), e1 in the
// plane of p and the normal (pointing up), e2 horizontal. Then
//
//   wi.z = cos(theta) p.z + sin(theta) cos(psi) e1.z,
//
// so the upper hemisphere is cos(psi) > -cos(theta) p.z / (sin(theta) e1.z):
// every psi for theta <= theta_a = asin(p.z) (the peak's elevation), a
// clipped range [0, psi_max] for theta_a < theta < pi - theta_a, none beyond.
// The clip is applied analytically, so the psi integrand is smooth on its
// range; so are the cones a lobe declares as its support (LobeHints::
// support: a cone about an axis d in the x-z plane meets a ring where
// wi.d = cos(theta) p.d + sin(theta) cos(psi) e1.d, linear in cos(psi), as
// the horizon does), and a ring is split where it crosses a declared kink
// cone. The theta axis is split at theta_a, at the width w and the narrow
// width aspect w (below) and where the rings touch a declared cone; a
// declared point kink (a point zero or cusp of f) is a
// break of theta, and a ring that passes near one is cut at psi about it.
// The piece from the peak up to aspect w is integrated in
// s = theta^2 (uniform in area near the peak), every other piece in
// ln(theta): a lobe of width w, or its tail, then takes the same number of
// nodes whatever w is, the ring integral of an elongated lobe, which falls
// as 1 / theta between aspect w and w, is smooth, and a piece that starts
// at the horizon clip is resolved on the scale of theta_a. (A lobe without
// a peak has w = aspect = 1 and every piece below 1 in s.) An end at
// the horizon clip or at a kink is flattened by a polynomial change of
// variable (the psi integral has a (theta - theta_a)^(3/2) kink there). The
// azimuth is integrated in psi' with tan(psi) = rho tan(psi'), rho(theta) =
// clamp(aspect w / theta, aspect, 1): an elongated lobe (a glossy lobe at
// grazing view is about mu_o + alpha times narrower across the plane of
// incidence than in it) is then a feature of width ~1 in psi'. Both levels
// use adaptive Gauss-Kronrod; each inner integral gets the tolerance its
// outer weight requires, and its error estimate is integrated along with
// the values, so the reported error (QUADPACK estimate of the outer rule
// plus the integrated inner estimates) covers both levels.
//
// Below the horizon. A transmission lobe (a BTDF, f_t(wo, wi) for wi.z < 0)
// is declared the same way, its peak below the horizon (the refracted
// direction), and integrated with LobeDomain::lower_hemisphere:
//
//   M_k(mu_o) = integral over wi.z < 0 of f(wo, wi) w_k(wo.h) |cos(theta_i)| dw_i.
//
// That is the integral above of the mirror image: wi' = (wi.x, wi.y, -wi.z)
// and the peak mirrored the same way lie in the upper hemisphere, the frame,
// the horizon clip and the break points are built there as above, and f and
// the weights are evaluated at wi itself. h stays the half vector wo + wi
// (normalized), which is not the microfacet normal of a refraction: a
// transmission lobe's moment of weight 1 (its albedo) is the one with a
// meaning. A lobe without a peak is then taken in coordinates about -z.
// Hints are those of the lobe as it is, below the horizon (width and
// aspect of the refracted peak, cones about it). The Monte Carlo estimates
// cover the upper hemisphere only.
//
// Requirements on the lobe: f is even in wi.y for wo in the x-z plane (an
// isotropic BRDF), the peak lies in the x-z plane, f is finite and
// thread-safe (const, no shared state). Every computation is deterministic:
// the same arguments give the same bits whatever thread calls.
//
// Rounding of the directions: wi reaches f as a unit vector in double, so
// near a peak of width w and aspect a (hints below) f carries a relative
// error of about 2^-53 / (w a) whatever the rule does (the half vector of a
// grazing wo and a wi next to its mirror direction is a difference of
// components near 1). The error estimate includes 2^-52 / (w a) times each
// moment's size for it. For a microfacet lobe (w = 2 alpha, a = mu_o +
// alpha) that keeps the 1e-7 target for alpha >= 2e-6 at mu_o >= 1/256 and,
// at exactly grazing view (mu_o = 0), for alpha >= 5e-5; the quadrature
// itself converges for widths down to 1e-12 (its nodes are placed relative
// to w).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "brdflut/math.h"
#include "brdflut/quadrature.h"

namespace brdflut {

// The directions within angle (radians, in [0, pi]) of the unit axis (in
// the x-z plane; for LobeDomain::lower_hemisphere mirrored with the peak, so
// given as it is). The polar angles about the peak where a ring touches the
// cone's edge (|gamma - angle|, gamma + angle, 2 pi - gamma - angle; gamma
// the axis's polar angle) are break points of the theta axis.
struct LobeCone {
    Vec3 axis{0.0, 0.0, 1.0};
    double angle = kPi;
};

// The shape of a lobe seen from one view direction wo.
struct LobeHints {
    // Unit direction where the lobe peaks (in the x-z plane; in the upper
    // hemisphere, or in the lower one for LobeDomain::lower_hemisphere);
    // without a peak the polar coordinates are taken about the normal
    // (-z below) with width 1.
    bool has_peak = false;
    Vec3 peak{0.0, 0.0, 1.0};
    // Angular scale (radians) of the peak in the plane of the peak and the
    // normal (e.g. 2 alpha for a microfacet lobe: wi turns twice as far as
    // the half vector). Clamped to [1e-12, 1].
    double width = 1.0;
    // Width across that plane over the width in it, in (0, 1].
    double aspect = 1.0;
    // Directions (unit, in the x-z plane, on the lobe's side of the
    // horizon) where f has a point singularity: a zero or a cusp that goes
    // as |angle|^q with q not an even integer (a Charlie sheen's
    // sin(theta_h)^(1/alpha) at the mirror direction, where h is the
    // normal). The ring through each is a break point, the rings next to
    // it are cut about it, and at the centre of the rings (the peak, or the
    // normal for a lobe without one) the first piece is integrated in
    // theta, flattened there, not in s.
    std::vector<Vec3> point_kinks;
    // Cones (see LobeCone) that bound the lobe's support: f is 0 outside
    // any of them. Each ring is clipped to them as to the horizon, so a lobe
    // that ends inside the domain (a refraction lobe ends at the largest
    // deviation from -wo, and where its microfacet normal reaches the
    // horizon) is integrated on its support only, where the rules see it
    // whole.
    std::vector<LobeCone> support;
    // Cones across which f has a kink or a jump (a Fresnel factor's
    // critical angle is a cone about wo): each ring is split where it
    // crosses one.
    std::vector<LobeCone> kink_cones;
};

// A direction drawn by a lobe's sampler and its density (per solid angle).
struct LobeSample {
    Vec3 wi;
    double pdf = 0.0;  // 0: no sample (the draw counts as a zero)
};

class GenericLobe {
public:
    virtual ~GenericLobe() = default;
    // The BRDF without the cosine, for unit wo (wo.z > 0, wo.y = 0) and wi
    // (wi.z < 0 for a transmission lobe: the BTDF).
    virtual double f(const Vec3& wo, const Vec3& wi) const = 0;
    virtual LobeHints hints(const Vec3& /*wo*/) const { return {}; }
    // View cosines in (0, 1) where the moments, as functions of mu_o, have a
    // kink (a jump in a low derivative, e.g. where a shadowing term of wo is
    // pieced together): the average over the view splits its range there.
    virtual std::vector<double> view_kinks() const { return {}; }
    // An importance sampler (optional): its density must be positive
    // wherever f is, so that the Monte Carlo estimate is unbiased.
    virtual bool has_sampler() const { return false; }
    virtual LobeSample sample(const Vec3& /*wo*/, double /*u1*/, double /*u2*/) const { return {}; }
    // The albedo and the Fresnel moment, {int f cos(theta_i) dw_i, int f (1 -
    // wo.h)^5 cos(theta_i) dw_i}, each to abs_tol, by a route of the lobe's
    // own that is cheaper than the generic path (optional; the LTC norms,
    // ltc_norms, take it). The generic path never does: it stays an
    // independent check of the route.
    virtual bool own_moments(double /*mu_o*/, double /*abs_tol*/, Estimate<2>& /*out*/) const { return false; }
};

// A term of f that is a pure function of a roughness and a cosine, such as
// a shadowing term of the view or of the light: the generic path asks for f
// at many wi of one wo, and about the normal every wi of a ring has the
// same cosine, so the value of the last (alpha, mu) this thread asked for is
// kept and `compute()` runs once per view (or per ring). Each call site has
// its own cache (the lambda's type makes its own instantiation).
template <class Compute>
double per_cosine(double alpha, double mu, Compute compute) {
    thread_local double kept_alpha = -1.0, kept_mu = -1.0, kept = 0.0;
    if (kept_alpha != alpha || kept_mu != mu) {
        kept = compute();
        kept_alpha = alpha;
        kept_mu = mu;
    }
    return kept;
}

// The sampler of the sheen lobes: an equal mixture of the cosine-weighted
// hemisphere and the mirror directions of normals. `normal(u, phi)` returns a
// normal drawn from the lobe's normal distribution for a uniform u and the
// azimuth phi, oriented as the lobe wants it seen from wo (a normal facing
// away from wo is no sample); normal_pdf(h) is that draw's density per solid
// angle at the unit half vector h of wo and wi.
template <class NormalDraw, class NormalPdf>
LobeSample cosine_and_mirror_mixture(const Vec3& wo, double u1, double u2, NormalDraw normal, NormalPdf normal_pdf) {
    LobeSample s;
    const bool cosine = u1 < 0.5;
    const double u = cosine ? 2.0 * u1 : 2.0 * u1 - 1.0;
    const double phi = kTwoPi * u2;
    if (cosine) {
        const double r = std::sqrt(u);
        s.wi = {r * std::cos(phi), r * std::sin(phi), safe_sqrt(1.0 - u)};
    } else {
        const Vec3 m = normal(u, phi);
        const double o_m = dot(wo, m);
        if (!(o_m > 0.0)) return {};
        s.wi = {2.0 * o_m * m.x - wo.x, 2.0 * o_m * m.y - wo.y, 2.0 * o_m * m.z - wo.z};
    }
    if (!(s.wi.z > 0.0)) return {};
    const Vec3 h{wo.x + s.wi.x, wo.y + s.wi.y, wo.z + s.wi.z};
    const double len = std::sqrt(dot(h, h));
    const Vec3 hn{h.x / len, h.y / len, h.z / len};
    const double o_h = dot(wo, hn);
    const double reflected = o_h > 0.0 ? normal_pdf(hn) / (4.0 * o_h) : 0.0;
    s.pdf = 0.5 * s.wi.z * kInvPi + 0.5 * reflected;
    return s;
}

// The hints of a microfacet reflection lobe of width alpha: its peak at the
// mirror direction, width 2 alpha in the plane of incidence (wi turns twice
// as far as the half vector), aspect min(1, mu_o + alpha) across it.
LobeHints microfacet_reflection_hints(const Vec3& wo, double alpha);

// A weight of the moments as a function of c = wo.h and one parameter p:
// w(c) = f(c, p). The Fresnel factors engines split out of their tables:
namespace moment_weight {
double one(double c, double p);                   // 1
double schlick(double c, double p);               // (1 - c)^5
double one_minus_schlick(double c, double p);     // 1 - (1 - c)^5
double schlick_power(double c, double p);         // (1 - c)^p: generalized Schlick
double f82(double c, double p);                   // c (1 - c)^6: the F82-tint correction (Kutz et al. 2021;
                                                  // the whole Fresnel in f82.h)
double dielectric_fresnel(double c, double p);    // exact unpolarized Fresnel reflectance at c, eta = p
// The exact dielectric Fresnel remapped from [F0, 1] to [0, 1]:
// (F(c, eta) - F0) / (1 - F0), F0 = ((eta - 1)/(eta + 1))^2, eta = p > 0,
// clamped to [0, 1] (0 at eta = 1). A Fresnel F0' + (F90 - F0') s that
// follows the dielectric's shape (Blender Cycles' generalized Schlick with a
// negative exponent) has the moments F0' M_1 + (F90 - F0') M_s.
double dielectric_remapped(double c, double p);
}  // namespace moment_weight
struct MomentWeight {
    double (*f)(double c, double p) = moment_weight::one;
    double p = 0.0;
    double operator()(double c) const { return f(c, p); }
};
inline constexpr MomentWeight kWeightOne{moment_weight::one};
// The split-sum weights: {1 - (1 - c)^5, (1 - c)^5}.
inline constexpr std::array<MomentWeight, 2> kSplitSumWeights = {MomentWeight{moment_weight::one_minus_schlick},
                                                                 MomentWeight{moment_weight::schlick}};

// The half angles (radians) of the cones about wo where weight w is not
// smooth (a cusp, a kink or a clamp in c = wo.h; wo.wi = 2 c^2 - 1): (1 - c)^p
// for a non-integer p below 6, the dielectric weights' total internal
// reflection (p < 1) and the remapped one's clamp where F dips below F0. The
// moments split the rings where they cross these cones, as they do the
// lobe's own kink cones (LobeHints::kink_cones).
std::vector<double> weight_view_cones(const MomentWeight& w);

// What is integrated over which directions.
enum class LobeDomain {
    hemisphere,  // f w_k cos(theta_i) over wi.z > 0 (the moments)
    sphere,      // f w_k over every wi, no cosine (for identities such as the weak white furnace)
    lower_hemisphere,  // f w_k |cos(theta_i)| over wi.z < 0 (a transmission lobe; see "Below the horizon")
};

// At mu_o = 0 the moments are evaluated at this view cosine (their limit).
inline constexpr double kGenericGrazingMu = 1e-16;

struct GenericOptions {
    double abs_tol = 1e-9;  // per moment
    LobeDomain domain = LobeDomain::hemisphere;
    int max_intervals = 400;  // per adaptive integral
};

// The moments at view cosine mu_o (wo = (sqrt(1 - mu_o^2), 0, mu_o)), up to
// four weights: value, estimated absolute error, evaluations of f.
template <std::size_t N>
Estimate<N> generic_moments(const GenericLobe& lobe, double mu_o, const std::array<MomentWeight, N>& weights,
                            const GenericOptions& opt = {});
// The directional albedo: the moment of weight 1.
Estimate<1> generic_albedo(const GenericLobe& lobe, double mu_o, const GenericOptions& opt = {});
// 2 * integral over mu in [0, 1] of M_k(mu) mu dmu, adaptive Gauss-Kronrod
// over mu (the view cosines below the lobe's width at normal view in
// mu = b u^2, above in ln(mu); both ranges split at the lobe's view_kinks),
// each M_k(mu) to the tolerance its weight needs; the error adds the outer
// estimate and the integrated inner ones.
template <std::size_t N>
Estimate<N> generic_moment_average(const GenericLobe& lobe, const std::array<MomentWeight, N>& weights,
                                   const GenericOptions& opt = {});
Estimate<1> generic_albedo_average(const GenericLobe& lobe, const GenericOptions& opt = {});

// Monte Carlo (the upper hemisphere): wi from the lobe's sampler if it has
// one, else cosine weighted; value = the mean of f w_k cos / pdf, error = its standard error.
// Seeded and reproducible.
template <std::size_t N>
Estimate<N> generic_moments_mc(const GenericLobe& lobe, double mu_o, const std::array<MomentWeight, N>& weights,
                               long long samples, std::uint64_t seed);
// The average: mu drawn with density 2 mu, then one wi per mu.
template <std::size_t N>
Estimate<N> generic_moment_average_mc(const GenericLobe& lobe, const std::array<MomentWeight, N>& weights,
                                      long long samples, std::uint64_t seed);

}  // namespace brdflut
