// Helpers shared by the tests: temporary folders, running the CLI, a table
// as a file would hold it.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include "brdflut/burley.h"
#include "brdflut/catalogue.h"
#include "brdflut/exr.h"
#include "brdflut/generate.h"
#include "brdflut/skin.h"
#include "integrate/ggx_simd.h"
#include "brdflut/table.h"

namespace brdflut::test {

// Burley's profile per channel at the skin tables' default albedo (0.8,
// 0.5, 0.3) and mean free path (1, 0.5, 0.25 mm), with the dmfp scaling.
inline SkinProfile burley_skin() {
    return {RadialProfile::burley(0.8, 1.0 / burley_scaling(0.8, BurleyScaling::dmfp)),
            RadialProfile::burley(0.5, 0.5 / burley_scaling(0.5, BurleyScaling::dmfp)),
            RadialProfile::burley(0.3, 0.25 / burley_scaling(0.3, BurleyScaling::dmfp))};
}

// The image of a table's values as stored in a float file, without
// metadata, as read_exr returns it.
inline ExrImage image_of(const Table& t) {
    ExrImage img;
    img.width = t.width();
    img.height = t.height();
    for (int c = 0; c < t.channel_count(); ++c) img.channel_names.push_back(std::string(1, "RGBA"[c]));
    for (double v : t.values) img.pixels.push_back(static_cast<float>(v));
    return img;
}

// The table generated on `threads` worker threads (0: all) with every
// result shared between tables cleared first, so that the run computes
// every texel itself (the thread-count tests compare such runs).
inline Table generate_fresh(const TableDefinition& def, const TableSettings& s, int threads) {
    clear_shared_results();
    GenerateOptions o;
    o.threads = threads;
    Table t = generate(def, s, o);
    clear_shared_results();
    return t;
}

// A fresh folder under the system temporary directory, removed at scope exit.
class TempDir {
public:
    TempDir() {
        std::random_device rd;
        path_ = std::filesystem::temp_directory_path() /
                ("brdflut-test-" + std::to_string(rd()) + std::to_string(rd()));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                     std::filesystem::perm_options::add, ec);
        std::filesystem::remove_all(path_, ec);
    }
    const std::filesystem::path& path() const { return path_; }
    std::string operator/(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

inline std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct CliResult {
    int exit_code = -1;
    std::string out, err;
};

// Runs the brdflut executable with the given arguments (a shell string).
inline CliResult run_cli(const std::string& args, const TempDir& scratch) {
    const std::string out = scratch / "stdout.txt", err = scratch / "stderr.txt";
    const std::string cmd = std::string("'") + BRDFLUT_CLI + "' " + args + " >'" + out + "' 2>'" + err + "' </dev/null";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(out);
    r.err = read_file(err);
    return r;
}

// Runs cases() at every SIMD width of the GGX integrands (1, and 2 and 4
// where the processor has them) and expects each width to give exactly the
// values, errors and evaluations of one node at a time; restores the widest.
template <class Cases>
void expect_same_bits_at_every_ggx_simd_width(const Cases& cases) {
    const int widest = brdflut::detail::ggx_phi_simd_width();
    brdflut::detail::set_ggx_phi_simd_width(1);
    const auto one = cases();
    for (int width : {2, 4}) {
        if (brdflut::detail::set_ggx_phi_simd_width(width) != width) continue;  // not on this processor
        const auto w = cases();
        EXPECT_EQ(w.size(), one.size());
        for (std::size_t n = 0; n < one.size() && n < w.size(); ++n) {
            EXPECT_EQ(w[n].value, one[n].value) << "width " << width << " case " << n;
            EXPECT_EQ(w[n].error, one[n].error) << "width " << width << " case " << n;
            EXPECT_EQ(w[n].evaluations, one[n].evaluations) << "width " << width << " case " << n;
        }
    }
    EXPECT_EQ(brdflut::detail::set_ggx_phi_simd_width(widest), widest);
}

}  // namespace brdflut::test
