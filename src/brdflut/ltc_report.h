// The error figures of an LTC (ltc.h) against the lobe it stands for
// (LtcLobe, ltc_fit.h), whether brdflut's fit or a foreign table's: the
// relative L3 error over the sphere, the mass below the horizon, and the
// integrated-light error over a fixed bank of polygon lights against the
// lobe's exact light (src/integrate/ltc_report.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "brdflut/ltc.h"
#include "brdflut/ltc_fit.h"
#include "brdflut/math.h"
#include "brdflut/microfacet.h"

namespace brdflut {

// The fixed bank of polygon lights the integrated-light error uses: squares
// of several angular sizes in the specular peak, off the peak and near the
// horizon, placed relative to the mirror direction of wo = (sin, 0, mu_o).
std::vector<LtcLight> ltc_light_bank(double mu_o);
inline constexpr std::size_t kLtcLightCount = 10;

struct LtcLightError {
    double max = 0;   // largest |n0' LTC(P) - exact(P)| / n0 over the bank
    double mean = 0;  // mean over the bank
    std::vector<double> per_light;
};
// The integrated-light error of an LTC (with its stored norm n0_stored)
// against the exact light, as a fraction of the exact norm n0.
LtcLightError ltc_light_error(const Mat3& minv, double n0_stored, const std::vector<LtcLight>& lights,
                              const std::vector<double>& exact, double n0);

// Every error figure of one texel of an LTC table (the fit's own, or a
// foreign table's): what `generate` records and `compare` reports.
struct LtcTexelReport {
    double relative_l3 = 0;
    double below_horizon = 0;
    double light_max = 0;
    double light_mean = 0;
};
// The reports of several LTCs of one lobe (a stored table's and a refit's):
// the lobe's exact norm and light are computed once for all of them.
struct LtcCandidate {
    Mat3 minv;
    double n0_stored = 0;
};
std::vector<LtcTexelReport> ltc_texel_reports(const LtcLobe& lobe, const std::vector<LtcCandidate>& candidates,
                                              const LtcFitOptions& opt = {});
LtcTexelReport ltc_texel_report(const LtcLobe& lobe, const Mat3& minv, double n0_stored,
                                const LtcFitOptions& opt = {});
LtcTexelReport ltc_texel_report(double mu_o, double alpha, Visibility vis, const Mat3& minv,
                                double n0_stored, const LtcFitOptions& opt = {});

}  // namespace brdflut
