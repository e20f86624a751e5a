// Failures while writing, interruptions, and the numerical edges of every
// table's domain.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "brdflut/catalogue.h"
#include "brdflut/generate.h"
#include "test_support.h"

using namespace brdflut;
using brdflut::test::run_cli;
using brdflut::test::TempDir;
namespace fs = std::filesystem;

namespace {
std::size_t entries(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

// Writes a first version of out/ggx_dfg.exr and returns its bytes.
std::string first_version(const TempDir& dir) {
    const auto r = run_cli("generate ggx_dfg --size 8 -q -o '" + (dir / "out") + "'", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return test::read_file(dir / "out/ggx_dfg.exr");
}
}  // namespace

TEST(Hardening, AFullDiskLeavesThePreviousFileAndNoPartialOne) {
    TempDir dir;
    const std::string before = first_version(dir);
    // A 1 KiB file-size limit makes the second, larger write fail part way.
    const auto r = run_cli("generate ggx_dfg --size 64 -o '" + (dir / "out") + "'; exit $?", dir);
    ASSERT_EQ(r.exit_code, 0);  // sanity: without a limit it succeeds
    const std::string second = test::read_file(dir / "out/ggx_dfg.exr");
    const std::string cmd = std::string("bash -c \"ulimit -f 1; '") + BRDFLUT_CLI + "' generate ggx_dfg --size 8 --range alpha=0.1:1 -o '" +
                            (dir / "out") + "'\" > '" + (dir / "err.txt") + "' 2>&1";
    const int status = std::system(cmd.c_str());
    EXPECT_NE(status, 0);
    EXPECT_NE(test::read_file(dir / "err.txt").find("brdflut: error: cannot write"), std::string::npos)
        << test::read_file(dir / "err.txt");
    EXPECT_EQ(test::read_file(dir / "out/ggx_dfg.exr"), second);
    EXPECT_EQ(entries(dir.path() / "out"), 1u);
    EXPECT_FALSE(before.empty());
}

TEST(Hardening, AnInterruptedRunLeavesThePreviousFileAndNoPartialOne) {
    TempDir dir;
    const std::string before = first_version(dir);
    // Interrupt a long run (SIGINT after 0.3 s, then SIGTERM).
    for (const char* sig : {"INT", "TERM"}) {
        const std::string cmd = std::string("timeout -s ") + sig + " 0.3 '" + BRDFLUT_CLI +
                                "' generate ggx_dfg --size 512 -q -o '" + (dir / "out") + "' 2>/dev/null";
        const int status = std::system(cmd.c_str());
        EXPECT_NE(status, 0) << sig;
        EXPECT_EQ(test::read_file(dir / "out/ggx_dfg.exr"), before) << sig;
        EXPECT_EQ(entries(dir.path() / "out"), 1u) << sig;
    }
}

TEST(Hardening, AnUnusableDestinationIsARuntimeErrorAndLeavesNoTemporaryFile) {
    TempDir dir;
    fs::create_directories(dir.path() / "out/ggx_albedo_avg.exr");  // a folder where the file should go
    const auto r = run_cli("generate ggx_albedo_avg --size 4 -o '" + (dir / "out") + "'", dir);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
    EXPECT_EQ(entries(dir.path() / "out"), 1u);
}

TEST(Hardening, EveryTableIsFiniteAtTheCornersAndLimitsOfItsDomain) {
    // End-point placement puts texels on every axis's limits (mu = 0 and 1,
    // alpha = 0 and 1, eta = 1, k = 0, sigma = 0, albedo 0 and 1, ...).
    for (const TableDefinition& d : catalogue()) {
        TableSettings s = default_settings(d);
        for (Axis& a : s.axes) {
            a.count = 3;
            a.placement = Placement::endpoints;
        }
        const Table t = generate(d, s);
        for (std::size_t i = 0; i < t.values.size(); ++i)
            EXPECT_TRUE(std::isfinite(t.values[i])) << d.id << " value " << i;
    }
}

TEST(Hardening, DomainLimitsEqualTheAnalyticLimits) {
    auto at = [](const std::string& id, std::vector<double> coords, int channel = 0) {
        const TableDefinition& d = find_table(id);
        const PreparedTable p = d.prepare(default_settings(d));
        return p.evaluator->evaluate(coords.data(), 0).value[static_cast<std::size_t>(channel)];
    };
    // GGX: the mirror limit at alpha = 0; the grazing limit at alpha = 1.
    EXPECT_DOUBLE_EQ(at("ggx_albedo", {0.5, 0.0}), 1.0);
    EXPECT_DOUBLE_EQ(at("ggx_dfg", {0.5, 0.0}, 1), std::pow(0.5, 5));
    EXPECT_NEAR(at("ggx_albedo", {0.0, 1.0}), 1.0, 1e-10);
    EXPECT_NEAR(at("ggx_albedo", {1.0, 1.0}), 1.0 - std::log(2.0), 1e-9);
    EXPECT_NEAR(at("ggx_albedo_avg", {0.0}), 1.0, 1e-12);
    // Fresnel: no interface at eta = 1; a conductor with k = 0 is a dielectric.
    EXPECT_EQ(at("fresnel_dielectric", {0.0, 1.0}), 0.0);
    EXPECT_EQ(at("fresnel_dielectric", {1.0, 1.0}), 0.0);
    EXPECT_DOUBLE_EQ(at("fresnel_dielectric", {0.0, 1.5}), 1.0);
    EXPECT_NEAR(at("fresnel_conductor_avg", {1.0, 0.0}), 0.0, 1e-12);
    // Diffuse models at zero roughness: Lambertian.
    for (double mu : {0.0, 0.5, 1.0}) {
        EXPECT_NEAR(at("oren_nayar_albedo", {mu, 0.0}), 1.0, 1e-9) << mu;
        EXPECT_NEAR(at("fujii_oren_nayar_albedo", {mu, 0.0}), 1.0, 1e-9) << mu;
        EXPECT_NEAR(at("eon_albedo", {mu, 1.0}), 1.0, 1e-6) << mu;
    }
    // Dipole: nothing scatters at albedo 0; all of it returns at albedo 1.
    EXPECT_EQ(at("dipole_total", {0.0}), 0.0);
    EXPECT_NEAR(at("dipole_total", {1.0}), 1.0, 1e-12);
    EXPECT_NEAR(at("dipole_albedo_inverse", {0.0}), 0.0, 1e-12);
    EXPECT_NEAR(at("dipole_albedo_inverse", {1.0}), 1.0, 1e-9);
}
