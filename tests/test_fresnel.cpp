// Fresnel reflectance, its hemispherical averages and the Fresnel tables,
// against closed forms, an independent real-valued conductor formula and
// Monte Carlo.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>

#include "brdflut/catalogue.h"
#include "brdflut/conductor_presets.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/fresnel.h"
#include "brdflut/fresnel_integrals.h"
#include "brdflut/generate.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::TempDir;

namespace {

double normal_incidence_dielectric(double eta) { return std::pow((eta - 1.0) / (eta + 1.0), 2); }

double normal_incidence_conductor(double eta, double k) {
    return (std::pow(eta - 1.0, 2) + k * k) / (std::pow(eta + 1.0, 2) + k * k);
}

// The exact conductor reflectance in real arithmetic (Born and Wolf; the
// form of pbrt-v3's FrConductor): with a^2 + b^2 = |n^2 - sin^2|,
// Rs = (a^2 + b^2 - 2 a cos + cos^2) / (a^2 + b^2 + 2 a cos + cos^2),
// Rp = Rs (cos^2 (a^2 + b^2) - 2 a cos sin^2 + sin^4) /
//         (cos^2 (a^2 + b^2) + 2 a cos sin^2 + sin^4).
double conductor_real_form(double c, double eta, double k) {
    const double c2 = c * c, s2 = 1.0 - c2;
    const double t0 = eta * eta - k * k - s2;
    const double a2b2 = std::sqrt(t0 * t0 + 4.0 * eta * eta * k * k);
    const double a = std::sqrt(0.5 * (a2b2 + t0));
    const double t1 = a2b2 + c2, t2 = 2.0 * c * a;
    const double rs = (t1 - t2) / (t1 + t2);
    const double t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    const double rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5 * (rs + rp);
}

TableSettings small(const std::string& id, int n) {
    TableSettings s = default_settings(find_table(id));
    for (Axis& a : s.axes) a.count = n;
    return s;
}

std::string error_of(const std::string& id, const TableSettings& s) {
    try {
        generate(find_table(id), s);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// ---- dielectric reflectance -----------------------------------------------

TEST(FresnelDielectric, NormalIncidenceMatchesClosedForm) {
    for (double eta : {0.4, 0.75, 1.0, 1.33, 1.5, 2.42, 4.0})
        EXPECT_NEAR(fresnel_dielectric(1.0, eta), normal_incidence_dielectric(eta), 1e-15) << eta;
}

TEST(FresnelDielectric, ParallelTermVanishesAtBrewsterAngle) {
    for (double eta : {0.6, 1.33, 1.5, 2.0, 3.0}) {
        const double cos_b = 1.0 / std::sqrt(1.0 + eta * eta);  // tan(theta_B) = eta
        const FresnelAmplitudes r = fresnel_dielectric_amplitudes(cos_b, eta);
        EXPECT_NEAR(r.rp, 0.0, 1e-15) << eta;
        EXPECT_GT(std::abs(r.rs), 0.05) << eta;
        EXPECT_NEAR(fresnel_dielectric(cos_b, eta), 0.5 * r.rs * r.rs, 1e-15) << eta;
        // rp changes sign across the Brewster angle.
        EXPECT_LT(fresnel_dielectric_amplitudes(cos_b - 0.01, eta).rp *
                      fresnel_dielectric_amplitudes(cos_b + 0.01, eta).rp,
                  0.0)
            << eta;
    }
}

TEST(FresnelDielectric, TotalInternalReflectionBelowTheCriticalCosine) {
    const double eta = 1.0 / 1.5, mu_c = std::sqrt(1.0 - eta * eta);
    for (double mu : {0.0, 0.2, 0.5, mu_c - 1e-9}) EXPECT_EQ(fresnel_dielectric(mu, eta), 1.0) << mu;
    EXPECT_LT(fresnel_dielectric(mu_c + 0.01, eta), 1.0);
    EXPECT_GT(fresnel_dielectric(mu_c + 1e-12, eta), 0.999);  // continuous at mu_c
    EXPECT_NEAR(fresnel_dielectric(1.0, eta), normal_incidence_dielectric(1.5), 1e-15);
}

TEST(FresnelDielectric, GrazingIncidenceReflectsEverythingAndMatchedIndexNothing) {
    for (double eta : {0.5, 1.2, 3.0}) EXPECT_DOUBLE_EQ(fresnel_dielectric(0.0, eta), 1.0);
    for (double mu : {0.0, 0.1, 0.5, 1.0}) {
        EXPECT_NEAR(fresnel_dielectric(mu, 1.0), 0.0, 1e-30) << mu;
        EXPECT_NEAR(fresnel_conductor(mu, 1.0, 0.0), 0.0, 1e-30) << mu;
    }
}

// ---- conductor reflectance -----------------------------------------------

TEST(FresnelConductor, NormalIncidenceMatchesClosedFormForBothForms) {
    for (double eta : {0.05, 0.5, 1.0, 2.9})
        for (double k : {0.0, 0.5, 3.0, 9.0}) {
            const double f0 = normal_incidence_conductor(eta, k);
            EXPECT_NEAR(fresnel_conductor(1.0, eta, k), f0, 1e-14) << eta << " " << k;
            EXPECT_NEAR(fresnel_conductor_approx(1.0, eta, k), f0, 1e-14) << eta << " " << k;
        }
}

TEST(FresnelConductor, WithZeroExtinctionEqualsDielectricIncludingTotalReflection) {
    for (double eta : {0.3, 0.667, 0.95, 1.0, 1.05, 1.33, 1.5, 2.5})
        for (int i = 0; i <= 400; ++i) {
            const double mu = i / 400.0;
            // Both round eta^2 - sin^2 to about 1e-16; near the critical angle
            // the square root amplifies that by 1 / sqrt(|eta^2 - sin^2|).
            const double tol = 2e-15 + 4e-16 / std::sqrt(std::abs(eta * eta - 1.0 + mu * mu) + 1e-30);
            EXPECT_NEAR(fresnel_conductor(mu, eta, 0.0), fresnel_dielectric(mu, eta), tol)
                << "eta " << eta << " mu " << mu;
        }
}

TEST(FresnelConductor, MatchesTheRealValuedExactForm) {
    std::vector<std::pair<double, double>> indices = {{0.2, 0.0}, {1.5, 1e-3}, {0.05, 0.3}, {3.0, 9.0}};
    for (const ConductorPreset& p : conductor_presets())
        for (int c = 0; c < 3; ++c) indices.emplace_back(p.eta[c], p.k[c]);
    for (const auto& [eta, k] : indices)
        for (int i = 0; i <= 200; ++i) {
            const double mu = i / 200.0;
            EXPECT_NEAR(fresnel_conductor(mu, eta, k), conductor_real_form(mu, eta, k), 1e-13)
                << "eta " << eta << " k " << k << " mu " << mu;
        }
}

TEST(FresnelConductor, ApproximationErrsAwayFromNormalIncidence) {
    // Silver at 550 nm: the real-valued form is off by about 2e-3 at mu = 0.5,
    // and badly for small k (a dielectric).
    const ConductorPreset& ag = conductor_preset("silver");
    const double d = fresnel_conductor_approx(0.5, ag.eta[1], ag.k[1]) -
                     fresnel_conductor(0.5, ag.eta[1], ag.k[1]);
    EXPECT_GT(std::abs(d), 5e-4);
    EXPECT_LT(std::abs(d), 1e-2);
    EXPECT_GT(std::abs(fresnel_conductor_approx(0.3, 1.5, 0.0) - fresnel_dielectric(0.3, 1.5)), 0.01);
    EXPECT_EQ(fresnel_conductor(0.5, 1.5, 2.0, FresnelForm::approx), fresnel_conductor_approx(0.5, 1.5, 2.0));
    EXPECT_EQ(fresnel_conductor(0.5, 1.5, 2.0, FresnelForm::exact), fresnel_conductor(0.5, 1.5, 2.0));
}

TEST(FresnelConductor, ReflectanceStaysWithinZeroAndOne) {
    for (double eta : {0.02, 0.3, 1.0, 4.0, 100.0})
        for (double k : {0.0, 1e-3, 2.0, 10.0, 100.0})
            for (int i = 0; i <= 64; ++i)
                for (FresnelForm form : {FresnelForm::exact, FresnelForm::approx}) {
                    const double f = fresnel_conductor(i / 64.0, eta, k, form);
                    EXPECT_GE(f, 0.0);
                    EXPECT_LE(f, 1.0 + 1e-15);
                }
}

TEST(FresnelForm, ParsesBothNamesAndRejectsOthers) {
    EXPECT_EQ(fresnel_form_from_string("exact"), FresnelForm::exact);
    EXPECT_EQ(fresnel_form_from_string(to_string(FresnelForm::approx)), FresnelForm::approx);
    EXPECT_THROW(fresnel_form_from_string("schlick"), Error);
}

// ---- presets --------------------------------------------------------------

TEST(ConductorPresets, CoverTheNamedMetalsWithPhysicalValues) {
    for (const char* name : {"gold", "silver", "copper", "aluminium", "iron", "chromium", "titanium",
                             "nickel", "platinum", "zinc"}) {
        const ConductorPreset& p = conductor_preset(name);
        EXPECT_FALSE(p.source.empty()) << name;
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(p.eta[c], 0.0) << name;
            EXPECT_GT(p.k[c], 1.0) << name;  // every one is a metal in the visible
            const double f0 = normal_incidence_conductor(p.eta[c], p.k[c]);
            EXPECT_GT(f0, 0.3) << name << " channel " << c;
            EXPECT_LT(f0, 1.0) << name << " channel " << c;
        }
    }
    EXPECT_EQ(conductor_presets().size(), 10u);
}

TEST(ConductorPresets, ColoursMatchTheMetals) {
    auto f0 = [](const char* name, int c) {
        const ConductorPreset& p = conductor_preset(name);
        return normal_incidence_conductor(p.eta[c], p.k[c]);
    };
    // Gold and copper are red-yellow: R > G > B, with a strong blue drop.
    for (const char* warm : {"gold", "copper"}) {
        EXPECT_GT(f0(warm, 0), f0(warm, 1)) << warm;
        EXPECT_GT(f0(warm, 1), f0(warm, 2)) << warm;
        EXPECT_GT(f0(warm, 0) - f0(warm, 2), 0.35) << warm;
    }
    // Silver and aluminium are bright and nearly neutral.
    for (const char* white : {"silver", "aluminium"})
        for (int c = 0; c < 3; ++c) EXPECT_GT(f0(white, c), 0.9) << white;
    // The grey transition metals are darker than silver in every channel.
    for (const char* grey : {"iron", "chromium", "titanium", "nickel", "platinum"})
        for (int c = 0; c < 3; ++c) EXPECT_LT(f0(grey, c), f0("silver", c) - 0.2) << grey;
}

TEST(ConductorPresets, UnknownNameListsTheKnownOnes) {
    try {
        conductor_preset("unobtainium");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("unobtainium"), std::string::npos) << msg;
        EXPECT_NE(msg.find("gold"), std::string::npos) << msg;
        EXPECT_NE(msg.find("zinc"), std::string::npos) << msg;
    }
}

// ---- hemispherical averages ------------------------------------------------

TEST(FresnelAverage, ClosedFormMatchesPublishedValues) {
    EXPECT_NEAR(fresnel_dielectric_average_closed_form(1.33), 0.065931, 5e-7);
    EXPECT_NEAR(fresnel_dielectric_average_closed_form(1.5), 0.091778, 5e-7);
    EXPECT_NEAR(fresnel_dielectric_average_closed_form(2.0), 0.160597, 5e-7);
    EXPECT_EQ(fresnel_dielectric_average_closed_form(1.0), 0.0);
    EXPECT_THROW(fresnel_dielectric_average_closed_form(0.9), Error);
}

TEST(FresnelAverage, QuadratureMatchesClosedFormToOneInABillion) {
    std::vector<double> etas = {1.01, 1.05, 1.33, 1.5, 2.0, 5.0, 20.0, 100.0};
    for (int i = 0; i < 16; ++i) etas.push_back(1.0 + (i + 0.5) / 8.0);  // the default axis span
    for (double eta : etas) {
        const double exact = fresnel_dielectric_average_closed_form(eta);
        const Estimate<1> q = fresnel_dielectric_average_quadrature(eta);
        EXPECT_NEAR(q.value[0], exact, 1e-9 * exact) << "eta " << eta;
        const Estimate<1> c = fresnel_conductor_average_quadrature(eta, 0.0);
        EXPECT_NEAR(c.value[0], exact, 1e-9 * exact) << "conductor, k = 0, eta " << eta;
        EXPECT_NEAR(fresnel_dielectric_average(eta), exact, 1e-9 * exact) << "eta " << eta;
    }
}

TEST(FresnelAverage, InsideAverageFollowsTheReciprocityRelation) {
    // F_avg(1/n) = 1 - (1 - F_avg(n)) / n^2, both sides by quadrature, and
    // against the closed form.
    for (double n : {1.01, 1.2, 1.33, 1.5, 2.0, 2.9, 10.0}) {
        const double inside = fresnel_dielectric_average_quadrature(1.0 / n).value[0];
        const double outside = fresnel_dielectric_average_quadrature(n).value[0];
        EXPECT_NEAR(inside, 1.0 - (1.0 - outside) / (n * n), 1e-9 * inside) << n;
        EXPECT_NEAR(inside, 1.0 - (1.0 - fresnel_dielectric_average_closed_form(n)) / (n * n),
                    1e-9 * inside)
            << n;
        EXPECT_NEAR(fresnel_conductor_average_quadrature(1.0 / n, 0.0).value[0], inside, 1e-9 * inside) << n;
    }
}

TEST(FresnelAverage, ErrorEstimateBoundsTheDifferenceToAMuchFinerRun) {
    const double etas[] = {1e-3, 0.02, 0.5, 0.999, 1.0, 1.0001, 1.01, 2.0, 4.0, 100.0};
    const double ks[] = {0.0, 1e-4, 0.05, 1.0, 10.0, 100.0};
    for (double eta : etas) {
        const Estimate<1> d = fresnel_dielectric_average_quadrature(eta, 1e-11);
        const Estimate<1> dref = fresnel_dielectric_average_quadrature(eta, 1e-15);
        EXPECT_LE(std::abs(d.value[0] - dref.value[0]), d.error[0] + 1e-15) << "eta " << eta;
        EXPECT_LE(d.error[0], 1e-11) << "eta " << eta;
        for (double k : ks)
            for (FresnelForm form : {FresnelForm::exact, FresnelForm::approx}) {
                const Estimate<1> c = fresnel_conductor_average_quadrature(eta, k, form, 1e-11);
                const Estimate<1> ref = fresnel_conductor_average_quadrature(eta, k, form, 1e-15);
                EXPECT_LE(std::abs(c.value[0] - ref.value[0]), c.error[0] + 1e-15)
                    << "eta " << eta << " k " << k << " " << to_string(form);
                EXPECT_LE(c.error[0], 1e-11) << "eta " << eta << " k " << k << " " << to_string(form);
            }
    }
}

TEST(FresnelAverage, AgreesWithMonteCarloWithinFourStandardErrors) {
    std::uint64_t seed = 11;
    for (double eta : {0.2, 0.667, 0.95, 1.02, 1.5, 3.0}) {
        const Estimate<1> q = fresnel_dielectric_average_quadrature(eta);
        const Estimate<1> m = fresnel_dielectric_average_mc(eta, 200000, ++seed);
        EXPECT_NEAR(q.value[0], m.value[0], 4.0 * m.error[0] + q.error[0]) << "eta " << eta;
    }
    for (double eta : {0.03, 0.4, 1.0, 2.5})
        for (double k : {0.0, 0.1, 3.0, 9.0})
            for (FresnelForm form : {FresnelForm::exact, FresnelForm::approx}) {
                const Estimate<1> q = fresnel_conductor_average_quadrature(eta, k, form);
                const Estimate<1> m = fresnel_conductor_average_mc(eta, k, form, 100000, ++seed);
                EXPECT_NEAR(q.value[0], m.value[0], 4.0 * m.error[0] + q.error[0])
                    << "eta " << eta << " k " << k << " " << to_string(form);
            }
}

TEST(FresnelAverage, ConductorAverageIsBoundedAndGrowsWithExtinction) {
    // Metals have a pseudo-Brewster dip, so F_avg may fall below F(1); it
    // stays within a few percent of it for the presets.
    for (const ConductorPreset& p : conductor_presets())
        for (int c = 0; c < 3; ++c) {
            const double avg = fresnel_conductor_average_quadrature(p.eta[c], p.k[c]).value[0];
            EXPECT_NEAR(avg, normal_incidence_conductor(p.eta[c], p.k[c]), 0.05) << p.name;
            EXPECT_LT(avg, 1.0) << p.name;
        }
    double prev = 0.0;
    for (double k : {0.0, 0.5, 1.0, 2.0, 5.0, 10.0}) {
        const double avg = fresnel_conductor_average_quadrature(1.5, k).value[0];
        EXPECT_GT(avg, prev) << k;
        prev = avg;
    }
}

// ---- tables ----------------------------------------------------------------

TEST(FresnelTables, ValuesMatchTheModelAtTheAxisParameters) {
    {
        TableSettings s = small("fresnel_dielectric", 8);
        s.axes[1].min = 0.5;  // include eta < 1 rows (total internal reflection)
        const Table t = generate(find_table("fresnel_dielectric"), s);
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i)
                EXPECT_EQ(t.at(static_cast<std::size_t>(j * 8 + i), 0),
                          fresnel_dielectric(t.axes[0].value(i), t.axes[1].value(j)));
    }
    {
        const Table t = generate(find_table("fresnel_dielectric_avg"), small("fresnel_dielectric_avg", 8));
        for (int i = 0; i < 8; ++i) {
            const double eta = t.axes[0].value(i);
            EXPECT_NEAR(t.at(static_cast<std::size_t>(i), 0), fresnel_dielectric_average_closed_form(eta), 1e-10);
            EXPECT_NEAR(t.at(static_cast<std::size_t>(i), 1),
                        1.0 - (1.0 - fresnel_dielectric_average_closed_form(eta)) / (eta * eta), 1e-10);
        }
    }
    {
        TableSettings s = small("fresnel_conductor", 8);
        s.params["metal"] = "copper";
        const Table t = generate(find_table("fresnel_conductor"), s);
        const ConductorPreset& cu = conductor_preset("copper");
        for (int i = 0; i < 8; ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(t.at(static_cast<std::size_t>(i), c),
                          fresnel_conductor(t.axes[0].value(i), cu.eta[c], cu.k[c]));
    }
    {
        TableSettings s = small("fresnel_conductor_avg", 6);
        s.params["fresnel"] = "approx";
        const Table t = generate(find_table("fresnel_conductor_avg"), s);
        for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 6; ++i) {
                const double eta = t.axes[0].value(i), k = t.axes[1].value(j);
                EXPECT_NEAR(eta, 0.02 + 3.98 * (i + 0.5) / 6, 1e-15);
                EXPECT_EQ(t.at(static_cast<std::size_t>(j * 6 + i), 0),
                          fresnel_conductor_average_quadrature(eta, k, FresnelForm::approx).value[0]);
            }
    }
}

TEST(FresnelTables, ExplicitIndexEqualsThePresetWithTheSameValues) {
    const ConductorPreset& au = conductor_preset("gold");
    TableSettings s = small("fresnel_conductor", 16);
    s.params["metal"] = "silver";  // overridden by --metal-eta and --metal-k
    auto csv = [](const std::array<double, 3>& v) {
        std::ostringstream o;
        o.precision(17);
        o << v[0] << "," << v[1] << "," << v[2];
        return o.str();
    };
    s.params["metal-eta"] = csv(au.eta);
    s.params["metal-k"] = csv(au.k);
    const Table custom = generate(find_table("fresnel_conductor"), s);
    const Table preset = generate(find_table("fresnel_conductor"), small("fresnel_conductor", 16));
    EXPECT_EQ(custom.values, preset.values);
    EXPECT_EQ(custom.model.at("material"), "custom");
    EXPECT_EQ(preset.model.at("material"), "gold");
    EXPECT_FALSE(custom.model.contains("wavelengths_nm"));
}

TEST(FresnelTables, MonteCarloTablesAgreeWithQuadratureTables) {
    for (const std::string id : {"fresnel_dielectric_avg", "fresnel_conductor_avg"}) {
        TableSettings s = small(id, 4);
        const Table q = generate(find_table(id), s);
        s.method = Method::monte_carlo;
        s.samples = 20000;
        s.seed = 5;
        const Table m = generate(find_table(id), s);
        EXPECT_EQ(m.method.at("name"), "mc");
        for (std::size_t v = 0; v < q.values.size(); ++v)
            EXPECT_NEAR(q.values[v], m.values[v], m.errors[v] + q.errors[v]) << id << " value " << v;
    }
}

TEST(FresnelTables, EveryTableRoundTripsThroughExrWithMetadataThatReproducesIt) {
    TempDir dir;
    struct Case {
        std::string id;
        std::map<std::string, std::string> params;
    };
    const Case cases[] = {{"fresnel_dielectric", {}},
                          {"fresnel_dielectric_avg", {}},
                          {"fresnel_conductor", {{"metal", "aluminium"}, {"fresnel", "approx"}}},
                          {"fresnel_conductor", {{"metal-eta", "0.2,0.9,1.3"}, {"metal-k", "3.5,2.6,2"}}},
                          {"fresnel_conductor_avg", {{"fresnel", "exact"}}}};
    for (const Case& c : cases) {
        TableSettings s = small(c.id, 7);
        s.axes[0].placement = Placement::endpoints;
        for (const auto& [name, value] : c.params) s.params[name] = value;
        const Table t = generate(find_table(c.id), s);
        const std::string path = dir / (c.id + ".exr");
        write_exr(path, t, PixelType::float32);
        const ExrImage img = read_exr(path);
        ASSERT_TRUE(img.has_metadata) << c.id;
        const auto& m = img.metadata;
        EXPECT_EQ(m.at("table"), c.id);
        EXPECT_EQ(img.channel_names.size(), t.channels.size()) << c.id;
        EXPECT_EQ(m.at("model"), t.model) << c.id;
        EXPECT_LT(m.at("error_bound").get<double>(), 1e-7) << c.id;
        // The metadata alone rebuilds the settings, and they give the same table.
        TableSettings again = default_settings(find_table(c.id));
        again.axes = axes_from_json(m.at("axes"));
        const auto& model = m.at("model");
        if (model.contains("fresnel") && again.params.count("fresnel"))
            again.params["fresnel"] = model.at("fresnel").get<std::string>();
        if (model.contains("material")) {
            if (model.at("material") == "custom") {
                std::ostringstream eta, k;
                eta.precision(17);
                k.precision(17);
                for (int i = 0; i < 3; ++i) {
                    eta << (i ? "," : "") << model.at("eta")[i].get<double>();
                    k << (i ? "," : "") << model.at("k")[i].get<double>();
                }
                again.params["metal-eta"] = eta.str();
                again.params["metal-k"] = k.str();
            } else {
                again.params["metal"] = model.at("material").get<std::string>();
            }
        }
        const Table rebuilt = generate(find_table(c.id), again);
        EXPECT_EQ(rebuilt.values, t.values) << c.id;
        for (std::size_t v = 0; v < t.values.size(); ++v)
            EXPECT_EQ(img.pixels[v], round_to_storage(t.values[v], PixelType::float32)) << c.id;
    }
}

TEST(FresnelTables, SameBytesForAnyThreadCount) {
    TempDir dir;
    for (const std::string id : {"fresnel_conductor_avg", "fresnel_dielectric_avg"}) {
        const TableSettings s = small(id, 12);
        GenerateOptions one, all;
        one.threads = 1;
        write_exr(dir / "1.exr", generate(find_table(id), s, one), PixelType::half);
        write_exr(dir / "0.exr", generate(find_table(id), s, all), PixelType::half);
        EXPECT_EQ(test::read_file(dir / "1.exr"), test::read_file(dir / "0.exr")) << id;
    }
}

TEST(FresnelTables, BadSettingsNameTheOptionTheValueAndWhatIsAllowed) {
    struct Case {
        std::string id, param, value, expect;
    };
    const Case cases[] = {
        {"fresnel_conductor", "metal-eta", "1,2", "has 2 value(s)"},
        {"fresnel_conductor", "metal-eta", "1,2,x", "--metal-eta '1,2,x'"},
        {"fresnel_conductor", "metal-eta", "0,1,1", "each > 0"},
        {"fresnel_conductor", "metal-eta", "1,1,1,1", "--metal-eta '1,1,1,1'"},
        {"fresnel_conductor", "metal-eta", "1,inf,1", "--metal-eta '1,inf,1'"},
        {"fresnel_conductor", "metal-k", "-1,0,0", "each >= 0"},
        {"fresnel_conductor", "metal", "tin", "allowed: gold, silver"},
        {"fresnel_conductor", "fresnel", "schlick", "allowed: exact, approx"},
        {"fresnel_conductor_avg", "fresnel", "fast", "allowed: exact, approx"},
    };
    for (const Case& c : cases) {
        TableSettings s = small(c.id, 4);
        s.params[c.param] = c.value;
        if (c.param == "metal-eta") s.params["metal-k"] = "1,1,1";
        if (c.param == "metal-k") s.params["metal-eta"] = "1,1,1";
        const std::string msg = error_of(c.id, s);
        EXPECT_NE(msg.find(c.expect), std::string::npos) << c.param << "=" << c.value << ": " << msg;
    }
    {
        TableSettings s = small("fresnel_conductor", 4);
        s.params["metal-k"] = "1,1,1";
        EXPECT_NE(error_of("fresnel_conductor", s).find("--metal-k was given without --metal-eta"), std::string::npos);
    }
    for (const std::string id : {"fresnel_dielectric", "fresnel_dielectric_avg", "fresnel_conductor_avg"}) {
        TableSettings s = small(id, 4);
        Axis& eta = s.axes[id == "fresnel_dielectric" ? 1 : 0];
        eta.min = 0.0;
        const std::string msg = error_of(id, s);
        EXPECT_NE(msg.find("axis 'eta' range 0:"), std::string::npos) << msg;
        EXPECT_NE(msg.find("allowed: 0 < eta <= 100"), std::string::npos) << msg;
        eta.min = 1.0;
        eta.max = 200.0;
        EXPECT_NE(error_of(id, s).find("outside the model's domain"), std::string::npos) << id;
    }
    TableSettings s = small("fresnel_conductor_avg", 4);
    s.axes[1].min = -0.5;
    EXPECT_NE(error_of("fresnel_conductor_avg", s).find("axis 'k' range -0.5:10"), std::string::npos);
}

TEST(FresnelTables, CommandLineAcceptsMaterialsAndRejectsBadIndices) {
    TempDir dir;
    const auto ok = test::run_cli("generate fresnel_conductor fresnel_dielectric --metal platinum "
                                  "--range eta=1.0:2.5 --count eta=16 --size 32 -q -o '" + (dir / "o") + "'",
                                  dir);
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    const ExrImage pt = read_exr(dir / "o/fresnel_conductor.exr");
    EXPECT_EQ(pt.metadata.at("model").at("material"), "platinum");
    EXPECT_EQ(pt.metadata.at("model").at("wavelengths_nm"), nlohmann::json({650.0, 550.0, 450.0}));
    const ExrImage d = read_exr(dir / "o/fresnel_dielectric.exr");
    EXPECT_EQ(d.width, 32);
    EXPECT_EQ(d.height, 16);
    EXPECT_EQ(d.metadata.at("axes")[1].at("max"), 2.5);
    const auto bad = test::run_cli("generate fresnel_conductor --metal-eta 1,2 --metal-k 1,1,1 -o '" + (dir / "p") + "'", dir);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--metal-eta '1,2'"), std::string::npos) << bad.err;
    const auto zero = test::run_cli("generate fresnel_dielectric_avg --range eta=0:2 -o '" + (dir / "p") + "'", dir);
    EXPECT_EQ(zero.exit_code, 2);
    EXPECT_NE(zero.err.find("allowed: 0 < eta"), std::string::npos) << zero.err;
}
