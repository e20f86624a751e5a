// The metal presets' spectral colours (brdflut/spectral.h): the CIE data
// against the chromaticities the CIE publishes, the shipped measured data
// against its source files and the three-wavelength presets, the colour
// conversions against the published sRGB matrix, and the reduced models
// against the spectral Fresnel at the angles they are matched at.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdflut/conductor_presets.h"
#include "brdflut/error.h"
#include "brdflut/f82.h"
#include "brdflut/fresnel.h"
#include "brdflut/spectral.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {
std::array<double, kCieSamples> constant(double v) {
    std::array<double, kCieSamples> a;
    a.fill(v);
    return a;
}

// The rows of a refractiveindex.info file's "tabulated nk" block.
std::vector<std::array<double, 3>> yaml_rows(const std::string& file) {
    std::ifstream in(std::string(BRDFLUT_SOURCE_DIR) + "/src/data/metals/" + file);
    std::vector<std::array<double, 3>> out;
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line.find("data: |") != std::string::npos) {
            inside = true;
            continue;
        }
        if (!inside) continue;
        std::istringstream s(line);
        std::array<double, 3> r{};
        if (!(s >> r[0] >> r[1] >> r[2])) break;
        out.push_back(r);
    }
    return out;
}
}  // namespace

// The CIE tables: 95 rows at 5 nm; the equal-energy spectrum at the
// equal-energy point (the colour-matching functions have equal areas) and
// D65 at its published chromaticity (CIE 015:2018, 0.31272, 0.32903), each
// to the rounding of 5 nm sums.
TEST(Spectral, CieDataGiveThePublishedChromaticities) {
    const auto& rows = cie_samples();
    for (int i = 0; i < kCieSamples; ++i)
        EXPECT_EQ(rows[static_cast<std::size_t>(i)].nm, kCieFirstNm + kCieStepNm * i);
    EXPECT_EQ(rows[58].zbar, 0.0);  // zbar vanishes from 650 nm
    const auto e = chromaticity(constant(1.0));
    EXPECT_NEAR(e[0], 1.0 / 3.0, 5e-5);
    EXPECT_NEAR(e[1], 1.0 / 3.0, 5e-5);
    std::array<double, kCieSamples> d65{};
    for (int i = 0; i < kCieSamples; ++i) d65[static_cast<std::size_t>(i)] = rows[static_cast<std::size_t>(i)].d65;
    const auto w = chromaticity(d65);
    EXPECT_NEAR(w[0], 0.31272, 3e-5);
    EXPECT_NEAR(w[1], 0.32903, 3e-5);
    EXPECT_EQ(rows[40].nm, 560.0);
    EXPECT_EQ(rows[40].d65, 100.0);  // D65 is normalised to 100 at 560 nm
    EXPECT_EQ(rows[39].ybar, 1.0);   // ybar peaks at 555 nm
}

// A perfect reflector is white in every space, a grey its grey; the sRGB
// conversion agrees with the matrix IEC 61966-2-1 publishes (to its four
// decimals) applied to XYZ under D65.
TEST(Spectral, ConversionsKeepWhiteAndMatchThePublishedSrgbMatrix) {
    for (ColourSpace s : kColourSpaces) {
        const auto one = reflectance_to_rgb(constant(1.0), s), half = reflectance_to_rgb(constant(0.5), s);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(one[static_cast<std::size_t>(c)], 1.0, 1e-12) << to_string(s);
            EXPECT_NEAR(half[static_cast<std::size_t>(c)], 0.5, 1e-12) << to_string(s);
        }
    }
    // A reflectance rising with wavelength (a warm colour).
    std::array<double, kCieSamples> r{};
    double x = 0, y = 0, z = 0, n = 0;
    for (int i = 0; i < kCieSamples; ++i) {
        const CieSample& s = cie_samples()[static_cast<std::size_t>(i)];
        r[static_cast<std::size_t>(i)] = 0.1 + 0.8 * i / (kCieSamples - 1.0);
        x += r[static_cast<std::size_t>(i)] * s.d65 * s.xbar;
        y += r[static_cast<std::size_t>(i)] * s.d65 * s.ybar;
        z += r[static_cast<std::size_t>(i)] * s.d65 * s.zbar;
        n += s.d65 * s.ybar;
    }
    x /= n, y /= n, z /= n;
    const double published[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    const auto rgb = reflectance_to_rgb(r, ColourSpace::srgb);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(rgb[static_cast<std::size_t>(c)], published[c][0] * x + published[c][1] * y + published[c][2] * z,
                    5e-4)
            << c;
    EXPECT_GT(rgb[0], rgb[1]);
    EXPECT_GT(rgb[1], rgb[2]);
    EXPECT_THROW(colour_space_from_string("xyz"), Error);
}

// The compiled spectra are the rows of the shipped files that cover 360 to
// 830 nm, and the three-wavelength presets (--metal) are those spectra at
// 650, 550 and 450 nm (the presets keep four decimals).
TEST(Spectral, ShippedSpectraAreTheSourceFilesAndGiveThePresets) {
    ASSERT_EQ(metal_spectra().size(), conductor_presets().size());
    for (const MetalSpectrum& m : metal_spectra()) {
        const auto file = yaml_rows(std::string(m.file));
        ASSERT_FALSE(file.empty()) << m.file;
        ASSERT_FALSE(m.rows.empty());
        EXPECT_LE(m.rows.front()[0], 0.36) << m.name;
        EXPECT_GE(m.rows.back()[0], 0.83) << m.name;
        std::size_t start = 0;
        while (start < file.size() && file[start][0] != m.rows.front()[0]) ++start;
        ASSERT_LE(start + m.rows.size(), file.size()) << m.name;
        for (std::size_t i = 0; i < m.rows.size(); ++i)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(m.rows[i][c], file[start + i][c]) << m.name << " row " << i;
        const ConductorPreset& p = conductor_preset(m.name);
        for (int c = 0; c < 3; ++c) {
            const auto nk = metal_nk(m, kPresetWavelengthsNm[static_cast<std::size_t>(c)]);
            EXPECT_NEAR(nk[0], p.eta[static_cast<std::size_t>(c)], 5e-5) << m.name << " " << c;
            EXPECT_NEAR(nk[1], p.k[static_cast<std::size_t>(c)], 5e-5) << m.name << " " << c;
        }
    }
    EXPECT_THROW(metal_spectrum("brass"), Error);
}

// Each reduced model is exact where it is matched: F0 at normal incidence,
// the F82-tint model and Gulbrandsen's at mu = 1/7; the spectral average
// agrees with a second rule; the errors reported are the largest over mu.
TEST(Spectral, ReducedModelsMatchTheSpectralFresnelWhereTheyAreFitted) {
    for (ColourSpace space : kColourSpaces)
        for (const MetalSpectrum& m : metal_spectra()) {
            const MetalColours c = metal_colours(m, space);
            const auto at82 = metal_fresnel_rgb(m, 1.0 / 7.0, space);
            for (std::size_t k = 0; k < 3; ++k) {
                const double b = f82_tint_b(c.f0[k], c.f82_tint[k]);
                EXPECT_NEAR(f82_tint_fresnel(1.0 / 7.0, c.f0[k], b), at82[k], 1e-12) << m.name;
                EXPECT_NEAR(f82_tint_fresnel(1.0, c.f0[k], b), c.f0[k], 1e-15);
                if (c.f0[k] < 0.9999 && c.edge_tint[k] > 0.0 && c.edge_tint[k] < 1.0) {
                    const auto [n, kk] = gulbrandsen_nk(c.f0[k], c.edge_tint[k]);
                    EXPECT_NEAR(fresnel_conductor(1.0, n, kk), c.f0[k], 1e-12) << m.name;
                    EXPECT_NEAR(fresnel_conductor(1.0 / 7.0, n, kk), at82[k], 1e-9) << m.name;
                }
                // Midpoint rule in mu, 1000 cells: error ~1e-7 for this smooth integrand.
                double avg = 0.0;
                for (int j = 0; j < 1000; ++j) {
                    const double mu = (j + 0.5) / 1000.0;
                    avg += 2.0 * mu * metal_fresnel_rgb(m, mu, space)[k] / 1000.0;
                }
                EXPECT_NEAR(c.average[k], avg, 1e-6) << m.name;
            }
            double worst = 0.0;
            for (int j = 0; j <= 200; ++j) {
                const double mu = j / 200.0;
                const auto f = metal_fresnel_rgb(m, mu, space);
                for (std::size_t k = 0; k < 3; ++k)
                    worst = std::max(worst, std::abs(f82_tint_fresnel(mu, c.f0[k], f82_tint_b(c.f0[k], c.f82_tint[k])) - f[k]));
            }
            EXPECT_EQ(c.error_f82, worst) << m.name;
            EXPECT_GT(c.error_schlick, c.error_f82) << m.name << " " << to_string(space);
        }
}

// Gulbrandsen's map: r is the normal-incidence reflectance of (n, k) for
// every g, and g = 1 (n = n_min) gives the brighter edge.
TEST(Spectral, GulbrandsenMapKeepsTheReflectivity) {
    for (double r : {0.02, 0.3, 0.7, 0.95})
        for (double g : {0.0, 0.3, 0.8, 1.0}) {
            const auto [n, k] = gulbrandsen_nk(r, g);
            EXPECT_NEAR(fresnel_conductor(1.0, n, k), r, 1e-12) << r << " " << g;
        }
    const auto lo = gulbrandsen_nk(0.5, 0.0), hi = gulbrandsen_nk(0.5, 1.0);
    EXPECT_LT(fresnel_conductor(0.1, lo[0], lo[1]), fresnel_conductor(0.1, hi[0], hi[1]));
}

TEST(Spectral, MetalsCommandPrintsEverySpaceAndRefusesUnknownNames) {
    TempDir dir;
    for (const char* space : {"srgb", "acescg", "rec2020"}) {
        const auto r = run_cli(std::string("metals --json --colour-space ") + space, dir);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const nlohmann::json j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j["colour_space"], space);
        ASSERT_EQ(j["metals"].size(), metal_spectra().size());
        const MetalColours gold = metal_colours(metal_spectrum("gold"), colour_space_from_string(space));
        EXPECT_EQ(j["metals"][0]["f0"][1].get<double>(), gold.f0[1]);
    }
    // One metal: its row alone, the same values as in the whole list.
    const auto one = run_cli("metals --json --metal copper --colour-space acescg", dir);
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const nlohmann::json c = nlohmann::json::parse(one.out);
    ASSERT_EQ(c["metals"].size(), 1u);
    EXPECT_EQ(c["metals"][0]["name"], "copper");
    EXPECT_EQ(c["metals"][0]["f82_tint"][2].get<double>(),
              metal_colours(metal_spectrum("copper"), ColourSpace::acescg).f82_tint[2]);
    const auto text = run_cli("metals --metal zinc", dir);
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("\nzinc "), std::string::npos) << text.out;
    EXPECT_EQ(text.out.find("gold"), std::string::npos) << text.out;
    const auto bad = run_cli("metals --colour-space xyz", dir);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("allowed: srgb, acescg, rec2020"), std::string::npos) << bad.err;
    const auto metal = run_cli("metals --metal brass", dir);
    EXPECT_EQ(metal.exit_code, 2);
    EXPECT_NE(metal.err.find("allowed: gold, silver"), std::string::npos) << metal.err;
}
