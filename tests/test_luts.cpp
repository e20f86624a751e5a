// The shipped table set: luts/ is exactly what its batch file generates.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>

#include "test_support.h"

using brdflut::test::run_cli;
using brdflut::test::TempDir;
namespace fs = std::filesystem;

namespace {
const fs::path kLuts = fs::path(BRDFLUT_SOURCE_DIR) / "luts";

// The committed bytes of luts/<name> when the source tree is a git checkout
// (so a stale luts/ is caught even after the main command rewrote it), else
// the file on disk.
std::string shipped_bytes(const std::string& name, const TempDir& scratch) {
    const std::string out = scratch / ("shipped-" + name);
    const std::string cmd = "git -C '" + std::string(BRDFLUT_SOURCE_DIR) + "' show 'HEAD:luts/" + name + "' > '" +
                            out + "' 2>/dev/null";
    if (std::system(cmd.c_str()) == 0) return brdflut::test::read_file(out);
    return brdflut::test::read_file((kLuts / name).string());
}

std::set<std::string> exr_files(const fs::path& dir) {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".exr") out.insert(e.path().filename().string());
    return out;
}
}  // namespace

TEST(Luts, RegeneratingFromTheBatchFileGivesTheShippedBytes) {
    TempDir dir, scratch;
    const auto r = run_cli("generate --config '" + (kLuts / "brdflut.toml").string() + "' -q -o '" +
                               dir.path().string() + "'",
                           dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::set<std::string> shipped = exr_files(kLuts), fresh = exr_files(dir.path());
    EXPECT_EQ(shipped, fresh);
    ASSERT_FALSE(shipped.empty());
    for (const std::string& f : shipped)
        EXPECT_TRUE(shipped_bytes(f, scratch) == brdflut::test::read_file(dir / f))
            << f << " differs from a fresh run: regenerate luts/ with the README's main command and commit it";
}

TEST(Luts, ReadmeDescribesEveryShippedFile) {
    const std::string readme = brdflut::test::read_file((kLuts / "README.md").string());
    for (const std::string& f : exr_files(kLuts)) EXPECT_NE(readme.find("`" + f + "`"), std::string::npos) << f;
}
