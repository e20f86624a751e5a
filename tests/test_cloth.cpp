// Unreal's legacy cloth lobe (D_InvGGX with Vis_Cloth): its distribution,
// the closed form at alpha = 1, the table against Monte Carlo and across
// thread counts, and the preset in Unreal's layout.
#include <gtest/gtest.h>

#include <cmath>

#include "brdflut/catalogue.h"
#include "brdflut/cloth_invggx.h"
#include "brdflut/generic_lobe.h"
#include "brdflut/math.h"
#include "test_support.h"

using namespace brdflut;

TEST(ClothInvGgx, DistributionIsUnrealsFormulaAndFlatAtAlphaOne) {
    for (double c : {0.0, 0.1, 0.5, 0.9, 1.0}) {
        EXPECT_NEAR(inv_ggx_distribution(1.0, c), kInvPi, 1e-15) << c;
        const double a2 = 0.3 * 0.3, d = c * c * (1.0 - a2) + a2;
        EXPECT_NEAR(inv_ggx_distribution(0.3, c), (1.0 + 4.0 * a2 * a2 / (d * d)) / (kPi * (1.0 + 4.0 * a2)), 1e-15);
    }
}

TEST(ClothInvGgx, AlbedoAtAlphaOneIsTheClosedFormAndItsLimits) {
    EXPECT_DOUBLE_EQ(inv_ggx_cloth_albedo_alpha_one(0.0), 0.5);   // 2 pi * integral of 1/(4 pi) dmu
    EXPECT_NEAR(inv_ggx_cloth_albedo_alpha_one(1.0), 0.25, 1e-15);  // V = 1/4 at normal view
    // The series near mu = 1 joins the closed form.
    EXPECT_NEAR(inv_ggx_cloth_albedo_alpha_one(0.999), inv_ggx_cloth_albedo_alpha_one(1.0 - 1.0001e-3), 1e-7);
    const InvGgxClothLobe lobe(1.0);
    GenericOptions opt;
    opt.abs_tol = 1e-11;
    for (double mu : {0.01, 0.2, 0.5, 0.8, 0.999})
        EXPECT_NEAR(generic_albedo(lobe, mu, opt).value[0], inv_ggx_cloth_albedo_alpha_one(mu), 1e-10) << mu;
}

TEST(ClothInvGgx, MomentsAgreeWithMonteCarloAndTheTableIsTheSameForAnyThreadCount) {
    const std::array<MomentWeight, 2> w = {MomentWeight{moment_weight::one}, MomentWeight{moment_weight::schlick}};
    for (double alpha : {0.01, 0.2, 0.6})
        for (double mu : {0.05, 0.5, 0.95}) {
            const InvGgxClothLobe lobe(alpha);
            GenericOptions opt;
            opt.abs_tol = 1e-10;
            const Estimate<2> q = generic_moments<2>(lobe, mu, w, opt);
            const Estimate<2> mc = generic_moments_mc<2>(lobe, mu, w, 200000, 7);
            for (std::size_t k = 0; k < 2; ++k)
                EXPECT_LE(std::abs(q.value[k] - mc.value[k]), 4.0 * mc.error[k] + 1e-12)
                    << "alpha " << alpha << " mu " << mu << " moment " << k;
        }
    const TableDefinition& def = find_table("cloth_invggx_moments");
    TableSettings s = default_settings(def);
    s.axes[0].count = 8;
    s.axes[1].count = 6;
    EXPECT_EQ(test::generate_fresh(def, s, 1).values, test::generate_fresh(def, s, 2).values);
}

TEST(ClothInvGgx, UnrealsLegacyPresetClampsRoughnessAtOneHundredth) {
    // alpha = max(r, 0.01)^2: rows below r = 0.01 hold the values at 0.01.
    const TableDefinition& def = find_table("unreal_cloth_energy_legacy");
    EXPECT_EQ(def.preset, "unreal");
    TableSettings s = default_settings(def);
    s.axes[0].count = 3;
    s.axes[1].count = 2;
    s.axes[1].max = 5e-5;  // alpha below 1e-4 on both rows
    const Table t = test::generate_fresh(def, s, 1);
    const PreparedTable p = def.prepare(default_settings(def));
    for (int i = 0; i < 3; ++i) {
        const double at[2] = {s.axes[0].value(i), 1e-4};
        const TexelValue want = p.evaluator->evaluate(at, 0);
        for (int j = 0; j < 2; ++j)
            EXPECT_EQ(t.values[static_cast<std::size_t>((j * 3 + i) * 2)], want.value[0]) << i << "," << j;
    }
}
