// The error figures of any LTC against the lobe it stands for (the fit's
// own, or a foreign table's): the relative L3 error over the sphere, the
// mass below the horizon, and the integrated-light error over a bank of
// polygon lights against the lobe's exact light. What `generate` records in
// the error tables and the metadata, and `compare` reports.
#include "brdflut/ltc_report.h"

#include <algorithm>
#include <cmath>

#include "brdflut/ltc.h"
#include "integrate/ltc_quadrature.h"

namespace brdflut {

using namespace ltc_detail;

// ---- The light bank ----

std::vector<LtcLight> ltc_light_bank(double mu) {
    mu = clamp_mu(mu);
    const double s = safe_sqrt(1.0 - mu * mu);
    const Vec3 r{-s, 0.0, mu};  // mirror direction
    return {
        square("peak 1 deg", r, 1.0),
        square("peak 5 deg", r, 5.0),
        square("peak 15 deg", r, 15.0),
        square("peak 40 deg", r, 40.0),
        square("off-peak 30 deg toward the view, 10 deg", rotate_y(r, 30.0), 10.0),
        square("off-peak 90 deg in azimuth, 10 deg", Vec3{0.0, s, mu}, 10.0),
        square("off-peak 45 deg toward the view, 30 deg", rotate_y(r, 45.0), 30.0),
        square("horizon, mirror side, 10 deg", from_angles(5.0, 180.0), 10.0),
        square("horizon, side, 10 deg", from_angles(5.0, 90.0), 10.0),
        square("overhead 60 deg", Vec3{0, 0, 1}, 60.0),
    };
}

LtcLightError ltc_light_error(const Mat3& minv, double n0_stored, const std::vector<LtcLight>& lights,
                              const std::vector<double>& exact, double n0) {
    LtcLightError e;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const double ltc = n0_stored * ltc_polygon_integral(minv, lights[i].vertices.data(), 4);
        const double err = std::abs(ltc - exact[i]) / n0;
        e.per_light.push_back(err);
        e.max = std::max(e.max, err);
        e.mean += err / static_cast<double>(lights.size());
    }
    return e;
}

std::vector<LtcTexelReport> ltc_texel_reports(const LtcLobe& lobe, const std::vector<LtcCandidate>& candidates,
                                              const LtcFitOptions& opt) {
    // The lobe's side, computed once for every candidate: its exact norm,
    // the fine grid of the L3 error (whose frame the exact light uses too)
    // and the exact light of the bank.
    const double n0 = ltc_norms(lobe).n0;
    const LtcFitOptions fine = ltc_fit_options(2);
    const Setup s = make_setup(lobe, n0, fine.radial_nodes, fine.azimuth_nodes);
    const std::vector<LtcLight> bank = ltc_light_bank(lobe.mu_o);
    std::vector<double> exact;
    for (const LtcLight& l : bank) exact.push_back(polygon_light(lobe, s.frame, l, opt.light_tolerance * n0));
    std::vector<LtcTexelReport> out;
    for (const LtcCandidate& c : candidates) {
        LtcTexelReport r;
        const LtcInverse inv = LtcInverse::from_matrix(c.minv);
        r.relative_l3 = relative_l3(s.grid, inv.matrix());
        r.below_horizon = below_horizon_of(inv);
        const LtcLightError l = ltc_light_error(c.minv, c.n0_stored, bank, exact, n0);
        r.light_max = l.max;
        r.light_mean = l.mean;
        out.push_back(r);
    }
    return out;
}

LtcTexelReport ltc_texel_report(const LtcLobe& lobe, const Mat3& minv, double n0_stored, const LtcFitOptions& opt) {
    return ltc_texel_reports(lobe, {{minv, n0_stored}}, opt).front();
}

LtcTexelReport ltc_texel_report(double mu, double alpha, Visibility vis, const Mat3& minv, double n0_stored,
                                const LtcFitOptions& opt) {
    return ltc_texel_report(LtcLobe(mu, alpha, vis), minv, n0_stored, opt);
}

}  // namespace brdflut
