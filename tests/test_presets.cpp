// Engine presets: each writes its tables in the engine's layout, the
// metadata describes that layout, and every value is a core integral at the
// texel's coordinates converted to the model's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>

#include "brdflut/catalogue.h"
#include "brdflut/error.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/ggx_integrals.h"
#include "brdflut/lobe_integrals.h"
#include "brdflut/microfacet.h"
#include "brdflut/sheen_integrals.h"
#include "tables/recipe.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;

namespace {
Table small(const std::string& id, int n) {
    const TableDefinition& def = find_table(id);
    TableSettings s = default_settings(def);
    for (Axis& a : s.axes) a.count = n;
    return generate(def, s);
}
// The stored value is the integral: within the table's error estimate and
// the reference's (both honest, tests/test_ggx.cpp and the others).
void expect_within(const Table& t, std::size_t texel, int channel, double value, double error) {
    const std::size_t k = texel * t.channels.size() + static_cast<std::size_t>(channel);
    EXPECT_NEAR(t.values[k], value, t.errors[k] + error + 1e-15)
        << t.id << " texel " << texel << " channel " << channel;
}
}  // namespace

TEST(Presets, EveryPresetWritesItsTablesWithTheirLayoutInTheMetadata) {
    TempDir dir;
    for (const Preset& p : presets()) {
        const auto r = run_cli("generate --preset " + p.name + " --size 4 -q -o '" + (dir / p.name) + "'", dir);
        ASSERT_EQ(r.exit_code, 0) << p.name << ": " << r.err;
        const auto tables = preset_tables(p.name);
        ASSERT_FALSE(tables.empty()) << p.name;
        for (const TableDefinition* def : tables) {
            const ExrImage img = read_exr(dir / (p.name + "/" + def->id + ".exr"));
            ASSERT_TRUE(img.has_metadata) << def->id;
            const auto& m = img.metadata;
            EXPECT_EQ(m["table"], def->id);
            EXPECT_EQ(m["model"]["preset"], p.name) << def->id;
            EXPECT_EQ(m["pixel"], std::string(to_string(p.pixel))) << def->id;
            EXPECT_EQ(img.pixel, p.pixel) << def->id;
            ASSERT_EQ(m["axes"].size(), def->axes.size()) << def->id;
            for (std::size_t i = 0; i < def->axes.size(); ++i) {
                const Axis& a = def->axes[i].axis;
                EXPECT_EQ(m["axes"][i]["name"], a.name) << def->id;
                EXPECT_EQ(m["axes"][i]["placement"], std::string(to_string(a.placement))) << def->id;
                EXPECT_EQ(m["axes"][i]["warp"], std::string(to_string(a.warp))) << def->id;
                EXPECT_EQ(m["axes"][i]["count"], 4) << def->id;
            }
            EXPECT_EQ(img.channel_names.size(), def->channels.size()) << def->id;
        }
    }
}

TEST(Presets, TheirLayoutsAreTheEnginesOwn) {
    auto axis = [](const std::string& id, int i) { return find_table(id).axes[static_cast<std::size_t>(i)].axis; };
    // Filament: 128 x 128 cell centres, perceptual roughness rows.
    EXPECT_EQ(axis("filament_dfg", 0).count, 128);
    EXPECT_EQ(axis("filament_dfg", 1).name, "roughness");
    EXPECT_EQ(axis("filament_dfg", 1).placement, Placement::center);
    // Unreal: 128 x 32.
    EXPECT_EQ(axis("unreal_dfg", 1).count, 32);
    // HDRP: 64 x 64 end points with x = sqrt(NdotV).
    const Axis h = axis("hdrp_fgd", 0);
    EXPECT_EQ(h.count, 64);
    EXPECT_EQ(h.placement, Placement::endpoints);
    EXPECT_DOUBLE_EQ(h.value(32), std::pow(32.0 / 63.0, 2));
    // Cycles: x = sqrt(alpha) at end points, then mu.
    const Axis c = axis("cycles_ggx_e", 0);
    EXPECT_EQ(c.name, "alpha");
    EXPECT_EQ(c.count, 32);
    EXPECT_DOUBLE_EQ(std::sqrt(c.value(10)), 10.0 / 31.0);
    EXPECT_EQ(axis("cycles_ggx_e", 1).name, "cos_theta");
    EXPECT_DOUBLE_EQ(axis("cycles_ggx_e", 1).value(31), 1.0);
}

TEST(Presets, FilamentValuesAreTheCoreIntegralsAtAlphaRoughnessSquared) {
    const Table t = small("filament_dfg", 5);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
            const double mu = (i + 0.5) / 5, r = (j + 0.5) / 5, alpha = r * r;
            const std::size_t texel = static_cast<std::size_t>(j * 5 + i);
            const Estimate<2> s = ggx_split_sum(mu, alpha, Visibility::height_correlated);
            const Estimate<1> cloth = sheen_charlie_albedo(mu, alpha);
            expect_within(t, texel, 0, s.value[1], s.error[1]);
            expect_within(t, texel, 1, s.value[0] + s.value[1], s.error[0] + s.error[1]);
            expect_within(t, texel, 2, cloth.value[0], cloth.error[0]);
        }
}

TEST(Presets, KarisNotesUseSchlickSmithUnrealTheJointApproxAndGodotMobileGltfHeightCorrelated) {
    const Table k = small("unreal_karis2013_dfg", 4), u = small("unreal_dfg", 4), g = small("godot_mobile_dfg", 4),
                l = small("gltf_ggx", 4), b = small("bevy_dfg", 4);
    for (std::size_t texel : {0u, 5u, 10u, 15u}) {
        const double mu = (static_cast<double>(texel % 4) + 0.5) / 4, r = (static_cast<double>(texel / 4) + 0.5) / 4;
        const Estimate<2> s = ggx_split_sum(mu, r * r, Visibility::schlick_smith);
        const Estimate<2> j = ggx_split_sum(mu, r * r, Visibility::smith_joint_approx);
        const Estimate<2> hc = ggx_split_sum(mu, r * r, Visibility::height_correlated);
        for (int c = 0; c < 2; ++c) {
            expect_within(k, texel, c, s.value[c], s.error[c]);
            expect_within(u, texel, c, j.value[c], j.error[c]);
            expect_within(g, texel, c, hc.value[c], hc.error[c]);
            expect_within(l, texel, c, hc.value[c], hc.error[c]);
            expect_within(b, texel, c, hc.value[c], hc.error[c]);
        }
    }
    const Table ch = small("gltf_charlie", 3);
    EXPECT_EQ(ch.at(4, 0), 0.0);
    EXPECT_EQ(ch.at(4, 1), 0.0);
    const Estimate<1> cloth = sheen_charlie_albedo(0.5, 0.25);
    expect_within(ch, 4, 2, cloth.value[0], cloth.error[0]);
}

TEST(Presets, HdrpStoresSquaredCosineColumnsAndDiffuseMinusOneHalf) {
    const Table t = small("hdrp_fgd", 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 1; i < 4; ++i) {
            const double mu = std::pow(i / 3.0, 2), r = j / 3.0;
            const std::size_t texel = static_cast<std::size_t>(j * 4 + i);
            const Estimate<2> s = ggx_split_sum(mu, r * r, Visibility::height_correlated);
            const Estimate<1> d = lobe_albedo(Lobe::disney_diffuse, mu, r);
            expect_within(t, texel, 0, s.value[1], s.error[1]);
            expect_within(t, texel, 1, s.value[0] + s.value[1], s.error[0] + s.error[1]);
            expect_within(t, texel, 2, d.value[0] - 0.5, d.error[0]);
        }
}

TEST(Presets, CyclesSwapsTheAxesAndClampsMuAndRoughnessAsItsGenerator) {
    const Table t = small("cycles_ggx_e", 5);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
            // cycles_precompute.cpp: rough = clamp(x/(nx-1), 1e-4, 1), mu = clamp(y/(ny-1), 1e-4, 1).
            const double rough = std::max(i / 4.0, 1e-4), mu = std::max(j / 4.0, 1e-4);
            const std::size_t texel = static_cast<std::size_t>(j * 5 + i);
            const Estimate<2> s = ggx_split_sum(mu, rough * rough, Visibility::height_correlated);
            expect_within(t, texel, 0, s.value[0] + s.value[1], s.error[0] + s.error[1]);
        }
    // The first row is E at mu = 1e-4, not the limit 1 of mu -> 0: at alpha = 1
    // it is 1 - 1e-4 ln(1 + 1e4).
    EXPECT_NEAR(t.at(4, 0), 1.0 - 1e-4 * std::log1p(1e4), 1e-7);
    // alpha = 1: E(mu) = 1 - mu ln(1 + 1/mu).
    EXPECT_NEAR(t.at(2 * 5 + 4, 0), 1.0 - 0.5 * std::log(3.0), 1e-9);
    const Table avg = small("cycles_ggx_e_avg", 3);
    EXPECT_NEAR(avg.at(2, 0), 4.0 / 3.0 * (1.0 - std::log(2.0)), 1e-9);
}

TEST(Presets, UnknownPresetNamesTheKnownOnes) {
    EXPECT_THROW(find_preset("nope"), Error);
    TempDir dir;
    const auto r = run_cli("generate --preset nope -o '" + (dir / "x") + "'", dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("filament"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cycles"), std::string::npos) << r.err;
    const auto both = run_cli("generate --preset cycles ggx_dfg -o '" + (dir / "x") + "'", dir);
    EXPECT_EQ(both.exit_code, 2);
}

TEST(Presets, ExplicitPixelTypeOverridesThePresets) {
    TempDir dir;
    const auto r = run_cli("generate --preset unreal --pixel half --size 3 -q -o '" + (dir / "u") + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_exr(dir / "u/unreal_dfg.exr").pixel, PixelType::half);
}

TEST(Presets, AllGeneratesTheDefaultSetOnlyAndListTagsPresets) {
    TempDir dir;
    const auto r = run_cli("generate --all --size 2 -q -o '" + (dir / "all") + "'", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "all/sheen_charlie_albedo.exr"));
    EXPECT_TRUE(std::filesystem::exists(dir / "all/ggx_dfg.exr"));
    for (const TableDefinition& d : catalogue()) {
        if (!d.preset.empty()) {
            EXPECT_FALSE(std::filesystem::exists(dir / ("all/" + d.id + ".exr"))) << d.id;
        }
    }

    const auto list = run_cli("list", dir);
    EXPECT_NE(list.out.find("filament_dfg [preset: filament]"), std::string::npos);
    const auto names = run_cli("list --presets", dir);
    for (const Preset& p : presets()) EXPECT_NE(names.out.find(p.name + "\n"), std::string::npos) << p.name;
}

namespace {
// The coordinate a recipe table's texel gives a core table's axis `name`: the
// axis of that name, or the square (root) of the axis whose square_name
// (root_name) it is, or the default of the pin that holds it.
double core_coordinate(const tables::RecipeTable& t, const std::string& name, const std::vector<double>& c) {
    for (std::size_t i = 0; i < t.axes.size(); ++i)
        if (t.axes[i].axis.name == name) return c[i];
    for (std::size_t i = 0; i < t.axes.size(); ++i) {
        if (t.axes[i].square_name == name) return c[i] * c[i];
        if (t.axes[i].root_name == name) return std::sqrt(c[i]);
    }
    for (const tables::AxisPin& pin : t.pins)
        if (pin.axis == name) return std::stod(pin.default_value);
    ADD_FAILURE() << t.id << ": nothing feeds " << name;
    return std::nan("");
}

TableSettings with(const TableDefinition& def, const std::map<std::string, std::string>& options, Method method) {
    TableSettings s = default_settings(def);
    for (const auto& [name, value] : options)
        if (s.params.count(name)) s.params[name] = value;
    s.method = method;
    s.samples = 64;
    s.seed = 7;
    return s;
}
}  // namespace

TEST(Presets, EveryRecipeNamesCoreTablesTheirChannelsAndOptions) {
    const auto& declared = tables::preset_declarations();
    ASSERT_EQ(declared.size(), presets().size());
    for (std::size_t i = 0; i < declared.size(); ++i) {
        const tables::PresetDeclaration& p = declared[i];
        EXPECT_EQ(presets()[i].name, p.preset.name);
        if (p.tables.empty()) {
            // Presets of fitted tables (ltc_tables.cpp) name this declaration.
            EXPECT_FALSE(preset_tables(p.preset.name).empty()) << p.preset.name;
            continue;
        }
        // Every recipe is in the catalogue; a family may add tables of its
        // own to the preset (Cycles' generalized-Schlick tables,
        // fresnel_moment_tables.cpp).
        std::size_t recipes = 0;
        for (const TableDefinition* d : preset_tables(p.preset.name)) recipes += d->family == "preset" ? 1 : 0;
        EXPECT_EQ(recipes, p.tables.size()) << p.preset.name;
        for (const tables::RecipeTable& t : p.tables) {
            const TableDefinition& def = find_table(t.id);
            EXPECT_EQ(def.preset, p.preset.name);
            ASSERT_EQ(def.channels.size(), t.channels.size()) << t.id;
            bool mc = true, identify = true;
            for (const tables::ChannelRecipe& c : t.channels)
                for (const auto* terms : {&c.terms, &c.den_terms})
                for (const tables::RecipeTerm& term : *terms) {
                    const TableDefinition& core = find_table(term.table);
                    EXPECT_TRUE(core.preset.empty()) << t.id << " reads " << term.table;
                    EXPECT_GE(term.channel, 0) << t.id;
                    EXPECT_LT(term.channel, static_cast<int>(core.channels.size())) << t.id << " " << term.table;
                    mc = mc && core.supports_monte_carlo;
                    identify = identify && core.searched_by_identify;
                    for (const AxisSpec& a : core.axes)
                        EXPECT_TRUE(std::isfinite(core_coordinate(t, a.axis.name, std::vector<double>(3, 0.25))))
                            << t.id << " " << term.table;
                }
            EXPECT_EQ(def.supports_monte_carlo, mc) << t.id;
            EXPECT_EQ(def.searched_by_identify, identify) << t.id;
            for (const auto& [name, value] : t.options) {
                bool taken = false;
                for (const tables::ChannelRecipe& c : t.channels)
                    for (const auto* terms : {&c.terms, &c.den_terms})
                        for (const tables::RecipeTerm& term : *terms)
                            for (const ModelOption& o : find_table(term.table).options) taken = taken || o.name == name;
                EXPECT_TRUE(taken) << t.id << " option " << name;
            }
        }
    }
}

TEST(Presets, RecipeMistakesAreRefusedWithTheBadValueAndWhatIsAllowed) {
    auto lookup = [](const std::string& id) -> const TableDefinition* {
        for (const TableDefinition& d : catalogue())
            if (d.id == id) return &d;
        return nullptr;
    };
    tables::RecipeTable t = tables::preset_declarations().front().tables.front();
    auto message = [&](const tables::RecipeTable& r) {
        try {
            tables::plan_recipe(r, lookup);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(t), "no error");
    tables::RecipeTable bad = t;
    bad.channels[0].terms[0].table = "ggx_nope";
    EXPECT_NE(message(bad).find("'ggx_nope' is not in the catalogue"), std::string::npos) << message(bad);
    bad = t;
    bad.channels[0].terms[0].channel = 5;
    EXPECT_NE(message(bad).find("channel 5 of core table 'ggx_dfg' does not exist; allowed 0 to 1"),
              std::string::npos)
        << message(bad);
    bad = t;
    bad.channels[0].terms[0].table = "unreal_dfg";
    EXPECT_NE(message(bad).find("belongs to preset 'unreal'"), std::string::npos) << message(bad);
    bad = t;
    bad.axes[1].square_name = "";
    EXPECT_NE(message(bad).find("no axis feeds axis 'alpha' of core table 'ggx_dfg'"), std::string::npos)
        << message(bad);
    bad = t;
    bad.options = {{"visibility", "beckmann"}};
    EXPECT_NE(message(bad).find("visibility = 'beckmann' is not allowed by core table 'ggx_dfg'; allowed:"),
              std::string::npos)
        << message(bad);
    bad.options = {{"fresnel", "exact"}};
    EXPECT_NE(message(bad).find("option 'fresnel' is taken by none of its core tables"), std::string::npos)
        << message(bad);
    // A pin holds a core axis no recipe axis feeds, and must hold one.
    bad = t;
    bad.pins = {{bad.axes[0].axis.name, "help", "0.5"}};
    EXPECT_NE(message(bad).find("pin '" + bad.axes[0].axis.name + "' names one of its own axes"), std::string::npos)
        << message(bad);
    bad.pins = {{"ior", "help", "1.5"}};
    EXPECT_NE(message(bad).find("pin 'ior' holds no axis of its core tables"), std::string::npos) << message(bad);
}

// Each preset table's value is its recipe over its core tables' values, within
// both error estimates, at the first, middle and last texel of every axis,
// by quadrature and by Monte Carlo (the same seed and texel index).
TEST(Presets, EveryPresetTableAgreesWithItsCoreTables) {
    for (const tables::PresetDeclaration& p : tables::preset_declarations())
        for (const tables::RecipeTable& t : p.tables)
            for (Method method : {Method::quadrature, Method::monte_carlo}) {
                const TableDefinition& def = find_table(t.id);
                const PreparedTable preset = def.prepare(with(def, {}, method));
                std::map<std::string, PreparedTable> cores;
                for (const tables::ChannelRecipe& c : t.channels)
                    for (const auto* terms : {&c.terms, &c.den_terms})
                    for (const tables::RecipeTerm& term : *terms)
                        if (!cores.count(term.table)) {
                            const TableDefinition& core = find_table(term.table);
                            cores.emplace(term.table, core.prepare(with(core, t.options, method)));
                        }
                for (int where = 0; where < 3; ++where) {
                    std::vector<double> c;
                    std::uint64_t texel = 0, stride = 1;
                    for (const AxisSpec& a : t.axes) {
                        const int i = where == 0 ? 0 : where == 1 ? a.axis.count / 2 : a.axis.count - 1;
                        c.push_back(a.axis.value(i));
                        texel += static_cast<std::uint64_t>(i) * stride;
                        stride *= static_cast<std::uint64_t>(a.axis.count);
                    }
                    const TexelValue v = preset.evaluator->evaluate(c.data(), texel);
                    for (std::size_t ch = 0; ch < t.channels.size(); ++ch) {
                        // Each sum and its error, then the ratio (recipe.h).
                        auto sum = [&](const std::vector<tables::RecipeTerm>& terms, double offset) {
                            double value = offset, err = 0.0;
                            for (const tables::RecipeTerm& term : terms) {
                                const TableDefinition& core = find_table(term.table);
                                std::vector<double> x;
                                for (const AxisSpec& a : core.axes) x.push_back(core_coordinate(t, a.axis.name, c));
                                const TexelValue cv = cores.at(term.table).evaluator->evaluate(x.data(), texel);
                                const auto k = static_cast<std::size_t>(term.channel);
                                value += term.coef * cv.value[k];
                                err += std::abs(term.coef) * cv.error[k];
                            }
                            return std::array<double, 2>{value, err};
                        };
                        const tables::ChannelRecipe& r = t.channels[ch];
                        auto [expected, error] = sum(r.terms, r.offset);
                        const auto [den, den_error] = sum(r.den_terms, r.den_offset);
                        error = (error + std::abs(expected / den) * den_error) / std::abs(den);
                        expected /= den;
                        EXPECT_NEAR(v.value[ch], expected, v.error[ch] + error + 1e-15)
                            << t.id << " channel " << ch << " texel " << texel << " " << to_string(method);
                        EXPECT_TRUE(std::isfinite(v.value[ch])) << t.id;
                    }
                }
            }
}
