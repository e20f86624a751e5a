// Every option of every subcommand against its domain: one line on stderr
// naming the option, the value and what is allowed; exit 2 for usage errors,
// 1 for failures at run time. Nothing is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_support.h"

using brdflut::test::run_cli;
using brdflut::test::TempDir;

TEST(CliMatrix, BadInputGivesAOneLineErrorNamingTheValueAndWhatIsAllowed) {
    TempDir dir;
    struct Case {
        std::string args;
        int code;
        std::vector<std::string> expect;  // substrings of the message
    };
    const std::string o = " -o '" + (dir / "out") + "'";
    std::ofstream(dir / "bad.toml") << "colour = \"red\"\n";
    const Case cases[] = {
        // generate: tables, sizes, axes
        {"generate nope" + o, 2, {"'nope'", "allowed: ggx_dfg"}},
        {"generate ggx_dfg --size 0" + o, 2, {"--size '0'", "1 to 16384"}},
        {"generate ggx_dfg --size -4" + o, 2, {"--size '-4'", "1 to 16384"}},
        {"generate ggx_dfg --size 16385" + o, 2, {"--size '16385'", "1 to 16384"}},
        {"generate ggx_dfg --size 16384" + o, 2, {"texels is too many", "at most 67108864"}},
        {"generate ggx_dfg --size 8x" + o, 2, {"--size '8x'"}},
        {"generate ggx_dfg --count alpha=0" + o, 2, {"--count alpha=0", "1 to 16384"}},
        {"generate ggx_dfg --count alpha=2.5" + o, 2, {"--count alpha=2.5"}},
        {"generate ggx_dfg --range alpha=0.5:0.5" + o, 2, {"0.5:0.5", "min and max must differ"}},
        {"generate ggx_dfg --range alpha=-0.1:1" + o, 2, {"-0.1:1", "allowed: within 0:1"}},
        {"generate ggx_dfg --range alpha=a:b" + o, 2, {"'a' is not a finite number"}},
        {"generate ggx_dfg --range alpha=0.1" + o, 2, {"expected AXIS=MIN:MAX"}},
        {"generate ggx_dfg --placement alpha=middle" + o, 2, {"'middle'", "allowed: center, endpoints"}},
        {"generate ggx_dfg --warp alpha=cubic" + o, 2, {"'cubic'", "allowed: linear, square, sqrt, log"}},
        {"generate ggx_dfg --warp alpha=log" + o, 2, {"warp 'log' needs min > 0"}},
        {"generate ggx_dfg --placement alpha=endpoints --count alpha=1" + o, 2, {"at least 2"}},
        {"generate ggx_dfg --range eta=1:2" + o, 2, {"no requested table has an axis named 'eta'"}},
        // generate: storage, method, threads
        {"generate ggx_dfg --pixel double" + o, 2, {"'double'", "allowed: half, float"}},
        {"generate ggx_dfg --format jpg" + o, 2, {"'jpg'", "exr"}},
        {"generate disney_diffuse_albedo --size 8 --format png16" + o, 2, {"disney_diffuse_albedo", "[0, 1]"}},
        {"generate ggx_dfg --method sobol" + o, 2, {"'sobol'", "allowed: quadrature, mc"}},
        {"generate ggx_dfg --method mc --samples 0" + o, 2, {"--samples 0", "1 to"}},
        {"generate fresnel_dielectric --method mc" + o, 2, {"no Monte Carlo method"}},
        {"generate ggx_dfg --threads 5000" + o, 2, {"--threads 5000", "0 (all cores) to 1024"}},
        {"generate ggx_dfg --threads abc" + o, 2, {"--threads"}},
        {"generate ggx_dfg --quality best" + o, 2, {"'best'", "draft"}},
        {"generate --preset unity" + o, 2, {"'unity'", "filament"}},
        {"generate --all ggx_dfg" + o, 2, {"not both"}},
        // generate: model options
        {"generate ggx_dfg --visibility smith" + o, 2, {"'smith'", "height_correlated"}},
        {"generate ggx_dfg --material gold" + o, 2, {"--material does not apply"}},
        {"generate fresnel_conductor --metal unobtainium" + o, 2, {"unobtainium", "gold"}},
        {"generate fresnel_conductor --metal-eta 1,2 --metal-k 1,2,3" + o, 2, {"--metal-eta"}},
        {"generate fresnel_conductor --metal-eta 1,2,3 --metal-k 1,-2,3" + o, 2, {"--metal-k", "-2"}},
        {"generate fresnel_dielectric --range eta=0:3" + o, 2, {"eta", "0 < eta"}},
        {"generate fresnel_conductor_avg --range k=-1:3" + o, 2, {"k", "-1:3"}},
        {"generate dipole_total --eta 0" + o, 2, {"--eta", "0"}},
        {"generate dipole_total --fdr guess" + o, 2, {"'guess'", "fit"}},
        {"generate dipole_total --range albedo=0:1.5" + o, 2, {"albedo", "0:1.5"}},
        {"generate dipole_profile_rgb --material jelly" + o, 2, {"jelly", "skin1"}},
        {"generate dipole_profile_rgb --sigma-s 1,2,3 --sigma-a 1,-1,1" + o, 2, {"sigma", "-1"}},
        {"generate oren_nayar_albedo --range sigma=-1:1" + o, 2, {"sigma", "-1:1"}},
        {"generate --config '" + (dir / "missing.toml") + "'" + o, 1, {"cannot read config", "missing.toml"}},
        {"generate --config '" + (dir / "bad.toml") + "'" + o, 2, {"key 'colour' is not an option of 'generate'"}},
        // other subcommands
        {"verify nope", 2, {"'nope'", "allowed:"}},
        {"verify ggx_dfg --samples 5", 2, {"--samples 5", "100 to"}},
        {"furnace phong", 2, {"'phong'", "ggx_kulla_conty"}},
        {"furnace eon --size 1", 2, {"--size 1", "2 to 1024"}},
        {"furnace eon --tolerance 2", 2, {"--tolerance", "0 to 1"}},
        {"compare '" + (dir / "missing.exr") + "'", 1, {"missing.exr", "no such file"}},
        {"inspect '" + (dir / "missing.exr") + "'", 1, {"missing.exr"}},
        {"sample '" + (dir / "missing.exr") + "' --at cos_theta=0.5", 1, {"missing.exr"}},
        {"frobnicate", 2, {"'frobnicate' is not a command", "generate"}},
    };
    for (const Case& c : cases) {
        const auto r = run_cli(c.args, dir);
        EXPECT_EQ(r.exit_code, c.code) << c.args << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("brdflut: error: ", 0), 0u) << c.args << "\n" << r.err;
        for (const std::string& e : c.expect) EXPECT_NE(r.err.find(e), std::string::npos) << c.args << "\n" << r.err;
    }
    // No file was written (a refused png16 comes after the folder is made).
    if (std::filesystem::exists(dir / "out")) {
        EXPECT_TRUE(std::filesystem::is_empty(dir / "out"));
    }
}
