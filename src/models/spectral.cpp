#include "brdflut/spectral.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "brdflut/error.h"
#include "brdflut/f82.h"
#include "brdflut/fresnel.h"
#include "brdflut/conductor_presets.h"
#include "brdflut/quadrature.h"

namespace brdflut {
namespace {

#include "models/cie_data.inc"
#include "models/metal_spectra.inc"

using Mat3 = std::array<std::array<double, 3>, 3>;
using Vec = std::array<double, 3>;

Vec mul(const Mat3& m, const Vec& v) {
    Vec out{};
    for (int i = 0; i < 3; ++i) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    return out;
}
Mat3 mul(const Mat3& a, const Mat3& b) {
    Mat3 out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return out;
}
Mat3 inverse(const Mat3& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Mat3 out{};
    out[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
    out[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
    out[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
    out[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
    out[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
    out[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
    out[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
    out[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
    out[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
    return out;
}
Vec xyz_of_xy(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

struct SpaceData {
    ColourSpace space;
    const char* name;
    double primaries[3][2];
    double white[2];
    const char* white_name;
};
constexpr SpaceData kSpaces[] = {
    {ColourSpace::srgb, "srgb", {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}, {0.3127, 0.3290}, "D65"},
    {ColourSpace::acescg, "acescg", {{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}}, {0.32168, 0.33767},
     "the ACES white"},
    {ColourSpace::rec2020, "rec2020", {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}}, {0.3127, 0.3290}, "D65"},
};
const SpaceData& data_of(ColourSpace s) {
    for (const SpaceData& d : kSpaces)
        if (d.space == s) return d;
    return kSpaces[0];
}

// RGB from XYZ (relative to Y = 1 white) of a space: the inverse of the
// matrix whose columns are the primaries scaled to sum to the white.
Mat3 xyz_to_rgb(const SpaceData& d) {
    Mat3 p{};
    for (int c = 0; c < 3; ++c) {
        const Vec v = xyz_of_xy(d.primaries[c][0], d.primaries[c][1]);
        for (int r = 0; r < 3; ++r) p[r][c] = v[r];
    }
    const Vec s = mul(inverse(p), xyz_of_xy(d.white[0], d.white[1]));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) p[r][c] *= s[c];
    return inverse(p);
}

// The linear Bradford transform from white `from` to white `to` (XYZ).
Mat3 bradford(const Vec& from, const Vec& to) {
    const Mat3 b = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
    const Vec f = mul(b, from), t = mul(b, to);
    Mat3 d{};
    for (int i = 0; i < 3; ++i) d[i][i] = t[i] / f[i];
    return mul(inverse(b), mul(d, b));
}

Vec reflectance_to_xyz(const std::array<double, kCieSamples>& r) {
    double x = 0.0, y = 0.0, z = 0.0, norm = 0.0;
    for (int i = 0; i < kCieSamples; ++i) {
        const CieSample& s = kCieRows[i];
        x += r[static_cast<std::size_t>(i)] * s.d65 * s.xbar;
        y += r[static_cast<std::size_t>(i)] * s.d65 * s.ybar;
        z += r[static_cast<std::size_t>(i)] * s.d65 * s.zbar;
        norm += s.d65 * s.ybar;
    }
    return {x / norm, y / norm, z / norm};
}

// XYZ under D65 (the data's white) to the space's RGB.
const Mat3& conversion(ColourSpace space) {
    static const std::array<Mat3, 3> all = [] {
        std::array<double, kCieSamples> one;
        one.fill(1.0);
        const Vec d65 = reflectance_to_xyz(one);
        std::array<Mat3, 3> out{};
        for (std::size_t i = 0; i < 3; ++i) {
            const SpaceData& d = kSpaces[i];
            out[i] = mul(xyz_to_rgb(d), bradford(d65, xyz_of_xy(d.white[0], d.white[1])));
        }
        return out;
    }();
    for (std::size_t i = 0; i < 3; ++i)
        if (kSpaces[i].space == space) return all[i];
    return all[0];
}

template <std::size_t N>
std::vector<std::array<double, 3>> rows_of(const double (&a)[N][3]) {
    std::vector<std::array<double, 3>> out;
    for (const auto& r : a) out.push_back({r[0], r[1], r[2]});
    return out;
}

// Gulbrandsen's reflectivity must lie in [0, 1): an F0 outside the space's
// gamut (gold's red in sRGB exceeds 1) is held just below 1.
double gulbrandsen_r(double f0) { return std::clamp(f0, 0.0, 0.9999); }

double schlick(double f0, double mu) {
    const double m = 1.0 - mu;
    return f0 + (1.0 - f0) * m * m * m * m * m;
}

}  // namespace

std::string_view to_string(ColourSpace s) { return data_of(s).name; }

ColourSpace colour_space_from_string(std::string_view s) {
    for (const SpaceData& d : kSpaces)
        if (s == d.name) return d.space;
    throw Error("colour space '" + std::string(s) + "' is not known; allowed: srgb, acescg, rec2020");
}

std::string colour_space_description(ColourSpace s) {
    const SpaceData& d = data_of(s);
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "%s: primaries (%g, %g), (%g, %g), (%g, %g), white %s (%g, %g); XYZ under D65 adapted to it by "
                  "the linear Bradford transform",
                  d.name, d.primaries[0][0], d.primaries[0][1], d.primaries[1][0], d.primaries[1][1],
                  d.primaries[2][0], d.primaries[2][1], d.white_name, d.white[0], d.white[1]);
    return buf;
}

const std::array<CieSample, kCieSamples>& cie_samples() {
    static const std::array<CieSample, kCieSamples> all = [] {
        std::array<CieSample, kCieSamples> out{};
        for (int i = 0; i < kCieSamples; ++i) out[static_cast<std::size_t>(i)] = kCieRows[i];
        return out;
    }();
    return all;
}

std::array<double, 2> chromaticity(const std::array<double, kCieSamples>& spd) {
    double x = 0.0, y = 0.0, z = 0.0;
    for (int i = 0; i < kCieSamples; ++i) {
        const CieSample& s = kCieRows[i];
        x += spd[static_cast<std::size_t>(i)] * s.xbar;
        y += spd[static_cast<std::size_t>(i)] * s.ybar;
        z += spd[static_cast<std::size_t>(i)] * s.zbar;
    }
    return {x / (x + y + z), y / (x + y + z)};
}

std::array<double, 3> reflectance_to_rgb(const std::array<double, kCieSamples>& reflectance, ColourSpace space) {
    return mul(conversion(space), reflectance_to_xyz(reflectance));
}

const std::vector<MetalSpectrum>& metal_spectra() {
    static const std::vector<MetalSpectrum> all = [] {
        std::vector<MetalSpectrum> out;
#define BRDFLUT_METAL(name, file) \
    out.push_back({#name, file, rows_of(k_##name##_nk)});
        BRDFLUT_METAL_SPECTRA(BRDFLUT_METAL)
#undef BRDFLUT_METAL
        return out;
    }();
    return all;
}

const MetalSpectrum& metal_spectrum(std::string_view name) {
    std::string known;
    for (const MetalSpectrum& m : metal_spectra()) {
        if (m.name == name) return m;
        known += (known.empty() ? "" : ", ") + std::string(m.name);
    }
    throw Error("metal '" + std::string(name) + "' has no measured spectrum; allowed: " + known);
}

std::array<double, 2> metal_nk(const MetalSpectrum& m, double nm) {
    const double um = nm * 1e-3;
    const auto& r = m.rows;
    auto hi = std::lower_bound(r.begin(), r.end(), um, [](const std::array<double, 3>& row, double v) {
        return row[0] < v;
    });
    if (hi == r.begin()) return {r.front()[1], r.front()[2]};
    if (hi == r.end()) return {r.back()[1], r.back()[2]};
    const auto lo = hi - 1;
    const double t = (um - (*lo)[0]) / ((*hi)[0] - (*lo)[0]);
    return {(*lo)[1] + t * ((*hi)[1] - (*lo)[1]), (*lo)[2] + t * ((*hi)[2] - (*lo)[2])};
}

std::array<double, 3> metal_fresnel_rgb(const MetalSpectrum& m, double mu, ColourSpace space) {
    std::array<double, kCieSamples> r{};
    for (int i = 0; i < kCieSamples; ++i) {
        const auto [n, k] = metal_nk(m, kCieRows[i].nm);
        r[static_cast<std::size_t>(i)] = fresnel_conductor(mu, n, k);
    }
    return reflectance_to_rgb(r, space);
}

std::array<double, 2> gulbrandsen_nk(double r, double g) {
    const double s = std::sqrt(r);
    const double n_min = (1.0 - r) / (1.0 + r), n_max = (1.0 + s) / (1.0 - s);
    const double n = g * n_min + (1.0 - g) * n_max;
    const double k2 = (r * (n + 1.0) * (n + 1.0) - (n - 1.0) * (n - 1.0)) / (1.0 - r);
    return {n, std::sqrt(std::max(0.0, k2))};
}

MetalColours metal_colours(const MetalSpectrum& m, ColourSpace space) {
    MetalColours out{};
    out.f0 = metal_fresnel_rgb(m, 1.0, space);
    const double mu82 = 1.0 / 7.0;
    const Vec at82 = metal_fresnel_rgb(m, mu82, space);
    for (int c = 0; c < 3; ++c) {
        const double f0 = out.f0[static_cast<std::size_t>(c)], target = at82[static_cast<std::size_t>(c)];
        out.f82_tint[static_cast<std::size_t>(c)] = target / schlick(f0, mu82);
        const double r = gulbrandsen_r(f0);
        // Gulbrandsen's g: the Fresnel at 1/7 rises with g (n from n_max down
        // to n_min, k up); bisection on [0, 1], clamped at the ends.
        auto at = [&](double g) {
            const auto [n, k] = gulbrandsen_nk(r, g);
            return fresnel_conductor(mu82, n, k);
        };
        double lo = 0.0, hi = 1.0;
        if (at(lo) >= target) {
            hi = 0.0;
        } else if (at(hi) <= target) {
            lo = 1.0;
        } else {
            for (int it = 0; it < 80; ++it) {
                const double mid = 0.5 * (lo + hi);
                (at(mid) < target ? lo : hi) = mid;
            }
        }
        out.edge_tint[static_cast<std::size_t>(c)] = 0.5 * (lo + hi);
    }
    // The spectral average: 2 * integral of F mu, per wavelength, by
    // Gauss-Legendre in mu (F is smooth in mu for a conductor).
    const GaussLegendre& rule = gauss_legendre(48);
    out.average = {0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < rule.x.size(); ++i) {
        const double mu = 0.5 * (rule.x[i] + 1.0);
        const Vec f = metal_fresnel_rgb(m, mu, space);
        for (std::size_t c = 0; c < 3; ++c) out.average[c] += rule.w[i] * mu * f[c];
    }
    const ConductorPreset* preset = nullptr;
    for (const ConductorPreset& p : conductor_presets())
        if (p.name == m.name) preset = &p;
    for (int j = 0; j <= 200; ++j) {
        const double mu = j / 200.0;
        const Vec f = metal_fresnel_rgb(m, mu, space);
        for (std::size_t c = 0; c < 3; ++c) {
            const double f0 = out.f0[c];
            out.error_schlick = std::max(out.error_schlick, std::abs(schlick(f0, mu) - f[c]));
            out.error_f82 = std::max(out.error_f82, std::abs(f82_tint_fresnel(mu, f0, f82_tint_b(f0, out.f82_tint[c])) - f[c]));
            const auto [n, k] = gulbrandsen_nk(gulbrandsen_r(f0), out.edge_tint[c]);
            out.error_gulbrandsen = std::max(out.error_gulbrandsen, std::abs(fresnel_conductor(mu, n, k) - f[c]));
            if (preset)
                out.error_three_wavelengths = std::max(
                    out.error_three_wavelengths, std::abs(fresnel_conductor(mu, preset->eta[c], preset->k[c]) - f[c]));
        }
    }
    return out;
}

}  // namespace brdflut
