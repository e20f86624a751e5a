// Fitting linearly transformed cosines (ltc.h) to a BRDF lobe: the lobes
// (LtcLobe), their exact norms, the fitter and its objective, and the bank
// of polygon lights the objective holds the LTC's light to near grazing
// view. The fit is described in src/integrate/ltc_fit.cpp; the error
// figures of a fitted (or any) LTC are in ltc_report.h.
//
// Heitz, Dupuy, Hill and Neubelt 2016, "Real-Time Polygonal-Light Shading
//   with Linearly Transformed Cosines"
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "brdflut/generic_lobe.h"
#include "brdflut/ltc.h"
#include "brdflut/math.h"
#include "brdflut/microfacet.h"

namespace brdflut {

// Heitz's smallest alpha (fitLTC.cpp MIN_ALPHA): below it the lobe is
// evaluated at this width (a mirror lobe has no finite LTC).
inline constexpr double kLtcMinAlpha = 1e-5;
// Heitz's largest view angle, theta_o <= 1.57: at mu_o -> 0 the half vector
// of the mirror lobe is lost to cancellation, and the lobe is evaluated at
// this cosine instead (cos(1.57)).
inline constexpr double kLtcMinMu = 7.963267107332633e-4;

// The lobes an LTC is fitted to. Each is described by LtcLobe: f cos for a
// direction, its exact norm n0 (the catalogue's own albedo quadrature of
// that lobe) and where its peak is looked for (the fit's initial guess);
// the fitter, the error figures and the light bank are the same for all.
// Any lobe declared by its BRDF alone (generic_lobe.h) is fitted as the
// kind `generic`, its norms by the generic path: a new lobe gets its LTC
// tables with no numerics of its own.
enum class LtcLobeKind {
    ggx,            // GGX microfacet (F = 1), param = alpha >= kLtcMinAlpha; n0, n1 by ggx_split_sum
    charlie_sheen,  // Charlie sheen with Neubelt's V (sheen.h), param = alpha >= kLtcSheenMinAlpha; n0 by sheen_charlie_albedo
    eon,            // EON rough diffuse at rho = 1 (oren_nayar.h), param = sigma in [0, 1]; n0 by lobe_albedo
    generic,        // a GenericLobe, param = its roughness as the declaring table states it; n0, n1 by generic_moments
};
std::string to_string(LtcLobeKind kind);

// Below this Charlie alpha the lobe is evaluated at it: the lobe at normal
// view is then a ring within about a degree of the horizon, and its albedo
// 2^(-1/(2 alpha)) (at alpha = 0.01, 1e-15) leaves no LTC worth fitting.
inline constexpr double kLtcSheenMinAlpha = 0.01;

// The lobe an LTC is fitted to: f(wo, wi) cos(theta_i), F = 1.
struct LtcLobe {
    LtcLobeKind kind = LtcLobeKind::ggx;
    double param = 0.0;  // the lobe's roughness as evaluated (clamped), see LtcLobeKind
    Ggx ggx{kLtcMinAlpha};  // GGX only: Ggx{param}
    Visibility vis = Visibility::height_correlated;  // GGX only
    Vec3 wo;
    double mu_o;

    // The GGX lobe at (mu_o, alpha).
    LtcLobe(double mu_o, double alpha, Visibility vis);
    // Any lobe at (mu_o, its parameter); vis is used by GGX only.
    LtcLobe(LtcLobeKind kind, double mu_o, double param, Visibility vis = Visibility::height_correlated);
    // A lobe declared by its BRDF alone, at mu_o: f cos(theta_i) = lobe.f(wo,
    // wi) cos(theta_i); n0 and n1 by generic_moments to norm_tolerance. param
    // (the lobe's roughness) and key (which lobe and options, e.g. a hash of
    // its name) identify it: two generic lobes with the same key, param and
    // mu_o must be the same function (fits are shared by them).
    LtcLobe(std::shared_ptr<const GenericLobe> lobe, double mu_o, double param, std::uint64_t key,
            double norm_tolerance);
    // f cos(theta_i) for a unit direction wi; 0 below the horizon.
    double operator()(const Vec3& wi) const;
    // Whether the lobe's peak lies near the mirror direction (GGX, and the
    // generic lobes whose hints declare a peak): its peak is then searched
    // about it only; other lobes (retro-reflecting diffuse, sheen rings
    // about the normal) are scanned over the whole plane of incidence.
    bool peaks_near_mirror() const { return peaked_; }
    // Directions where f has a point singularity (a generic lobe's
    // LobeHints::point_kinks; the Charlie lobe's mirror direction, where D
    // = sin(theta_h)^(1/alpha) has its zero): the exact light of a polygon
    // (ltc_quadrature.h, polygon_light) cuts its rays about them.
    std::vector<Vec3> point_kinks() const;

    // The generic kind's lobe, its identity and its norms' tolerance.
    std::shared_ptr<const GenericLobe> generic;
    std::uint64_t key = 0;
    double norm_tolerance = 0.0;
    // The generic kind's norms when they are known (known_n0 >= 0, with its
    // error; n1 is 0 for a lobe without Fresnel): ltc_norms returns them
    // instead of integrating f. A lobe that knows its albedo in closed form
    // sets them, and a table run sets the norms it has computed once for
    // the texel, so that the fit, its error report and the norm tables do
    // not integrate f again.
    double known_n0 = -1.0, known_n0_error = 0.0;
    double known_n1 = 0.0, known_n1_error = 0.0;

private:
    bool peaked_ = true;
};

// The exact norms of a lobe: n0 = int f cos, and for GGX n1 = int f (1 -
// v.h)^5 cos (0 for the lobes without Fresnel), by the same quadrature and
// tolerance as the catalogue's albedo table of that lobe (ggx_albedo /
// ggx_dfg, sheen_charlie_albedo, eon_albedo).
struct LtcNorms {
    double n0 = 0, n1 = 0, n0_error = 0, n1_error = 0;
};
LtcNorms ltc_norms(const LtcLobe& lobe);

struct LtcFitOptions {
    int radial_nodes = 28;   // Gauss-Legendre nodes of the objective along each ray above the horizon
    int azimuth_nodes = 16;  // rays about the lobe's peak on [0, pi]
    // Of each exact light integral of the error report and of the fit's
    // light term (ltc_fit_light_bank), relative to n0 (the light errors
    // that matter are 1e-3 of n0 and more).
    double light_tolerance = 1e-5;
    // The two-parameter form of Zeltner, Burley and Chiang 2022: no rotation
    // and m22 = m11, so M^-1 = [[a, 0, b], [0, a, 0], [0, 0, 1]] up to scale
    // (params[0] = 0, params[2] = params[1]).
    bool two_parameter = false;
};
// Options for a quality (draft, standard, reference).
LtcFitOptions ltc_fit_options(int quality_level);

struct LtcFit {
    LtcInverse minv;           // normalized by the middle element
    double n0 = 0, n1 = 0;     // ltc_norms: int f cos, int f (1 - v.h)^5 cos (GGX; 0 otherwise)
    double n0_error = 0, n1_error = 0;
    double objective = 0;      // the fit's objective (Heitz's measure, + 0.3 x triangular discrimination for sheen and EON, + the light term near grazing; ltc_fit.cpp)
    double below_horizon = 0;  // LTC mass below the horizon (of 1)
    std::array<double, 4> params{};  // the optimizer's (theta, ln m11, ln m22, m13 / m11)
    int evaluations = 0;
};

// Fits the LTC of a lobe. Deterministic: depends on nothing but its arguments.
LtcFit fit_ltc(const LtcLobe& lobe, const LtcFitOptions& opt = {});
// The same descent from given optimizer parameters (LtcFit::params) instead
// of the initial guess from the lobe's shape (nullptr: as fit_ltc), e.g.
// from a neighbouring texel's fit: the tests hold every fitted texel to the
// continuation of its neighbours' minima.
LtcFit fit_ltc_from(const LtcLobe& lobe, const std::array<double, 4>* start, const LtcFitOptions& opt = {});
// Fits the LTC of the GGX lobe at (mu_o, alpha) (alpha below kLtcMinAlpha
// is raised to it): fit_ltc(LtcLobe(mu_o, alpha, vis)).
LtcFit fit_ggx_ltc(double mu_o, double alpha, Visibility vis, const LtcFitOptions& opt = {});

// The fit's objective at given optimizer parameters (for tests: a fitted
// texel is a local minimum of this).
double ltc_objective(const LtcLobe& lobe, const std::array<double, 4>& params, const LtcFitOptions& opt = {});
// The largest relative drop of the objective, (J(fit) - J(probe)) / J(fit),
// over the probes that move one parameter of a fit by 1e-3 either way
// (theta by 1e-3 of the lobe's width, exp(params[1]) capped at 1): at most
// 0, up to rounding, at a local minimum. verify and the tests confirm fits
// with it.
double ltc_local_minimum_drop(const LtcLobe& lobe, const LtcFit& fit, const LtcFitOptions& opt = {});
double ltc_objective(double mu_o, double alpha, Visibility vis, const std::array<double, 4>& params,
                     const LtcFitOptions& opt = {});
// M^-1 (normalized) from the optimizer's parameters.
LtcInverse ltc_inverse_from_params(const std::array<double, 4>& params);

// A polygon light of the light banks: this fit's (ltc_fit_light_bank) and
// the error report's (ltc_light_bank, ltc_report.h).
struct LtcLight {
    const char* name;
    std::array<Vec3, 4> vertices;  // unit directions, counter-clockwise seen from the origin
};

// The bank of eight square lights that the fit's objective holds the LTC's
// light to near grazing view (mu_o < 0.4, src/integrate/ltc_fit.cpp); not
// the report's bank (ltc_light_bank): squares of 3, 10 and 25 degrees on the
// mirror direction, 15 degrees at 20 degrees from it toward the view, 10 degrees
// at 15 degrees beyond it (below the horizon at grazing view), 20 degrees at
// 120 degrees in azimuth, 12 degrees at the horizon at 160 degrees, and 35
// degrees at 31 degrees from the normal toward the view.
std::vector<LtcLight> ltc_fit_light_bank(double mu_o);
// The weight of the triangular discrimination in a lobe's objective:
// kLtcWideLobeMassWeight for the wide lobes (sheen, EON, generic lobes
// without a peak), 0 for the lobes that peak near the mirror direction
// (GGX, generic lobes with a peak), whose grazing rows the light term
// covers (src/integrate/ltc_fit.cpp, objective()).
inline constexpr double kLtcWideLobeMassWeight = 0.3;
double ltc_mass_weight(const LtcLobe& lobe);
// The light term's weight: kLtcFitLightWeight (1 - mu_o / kLtcFitLightMu)^2
// below kLtcFitLightMu, 0 above (src/integrate/ltc_fit.cpp says why).
inline constexpr double kLtcFitLightWeight = 3.0;
inline constexpr double kLtcFitLightMu = 0.4;

}  // namespace brdflut
