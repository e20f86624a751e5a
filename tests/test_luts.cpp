// The shipped table set: luts/ holds what its batch file generates, value for
// value, with the same structured metadata (prose in the metadata, such as a
// rule's description, may be reworded without regenerating the files).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <set>

#include "brdflut/exr.h"
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

// The metadata without its prose: every string that contains a space (a
// description) is dropped; names, enumerations, numbers and keys stay.
nlohmann::json structured(const nlohmann::json& j) {
    if (j.is_object()) {
        nlohmann::json out = nlohmann::json::object();
        for (const auto& [k, v] : j.items())
            if (!(v.is_string() && v.get<std::string>().find(' ') != std::string::npos)) out[k] = structured(v);
        return out;
    }
    if (j.is_array()) {
        nlohmann::json out = nlohmann::json::array();
        for (const auto& v : j)
            if (!(v.is_string() && v.get<std::string>().find(' ') != std::string::npos)) out.push_back(structured(v));
        return out;
    }
    return j;
}

std::set<std::string> exr_files(const fs::path& dir) {
    std::set<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".exr") out.insert(e.path().filename().string());
    return out;
}
}  // namespace

TEST(Luts, RegeneratingFromTheBatchFileGivesTheShippedValuesAndMetadata) {
    TempDir dir, scratch;
    const auto r = run_cli("generate --config '" + (kLuts / "brdflut.toml").string() + "' -q -o '" +
                               dir.path().string() + "'",
                           dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::set<std::string> shipped = exr_files(kLuts), fresh = exr_files(dir.path());
    EXPECT_EQ(shipped, fresh);
    ASSERT_FALSE(shipped.empty());
    for (const std::string& f : shipped) {
        const std::string bytes = shipped_bytes(f, scratch);
        const brdflut::ExrImage old = brdflut::read_exr_memory(bytes.data(), bytes.size(), f);
        const brdflut::ExrImage now = brdflut::read_exr(dir / f);
        const char* regenerate = ": regenerate luts/ with the README's main command and commit it";
        EXPECT_EQ(old.width, now.width) << f << regenerate;
        EXPECT_EQ(old.height, now.height) << f << regenerate;
        EXPECT_EQ(old.channel_names, now.channel_names) << f << regenerate;
        EXPECT_TRUE(old.pixels == now.pixels) << f << ": values differ from a fresh run" << regenerate;
        EXPECT_EQ(structured(old.metadata), structured(now.metadata)) << f << ": metadata differs" << regenerate;
    }
}

TEST(Luts, ReadmeLinksTheReferenceThatDescribesEveryShippedFile) {
    // luts/README.md points to the generated table reference, which has a
    // section for the table of every shipped file.
    const std::string readme = brdflut::test::read_file((kLuts / "README.md").string());
    EXPECT_NE(readme.find("(../docs/reference/tables.md)"), std::string::npos);
    const std::string tables =
        brdflut::test::read_file(std::string(BRDFLUT_SOURCE_DIR) + "/docs/reference/tables.md");
    for (const std::string& f : exr_files(kLuts)) {
        const std::string id = f.substr(0, f.size() - 4);
        EXPECT_NE(tables.find("### `" + id + "`"), std::string::npos) << f;
    }
}
