// Every brdflut command line that README.md and the pages of docs/ quote
// runs here as quoted, with the exit status its text gives.
//
// A command line is a line of a ```sh block that starts with `brdflut ` or
// `./build/brdflut ` (continued over lines ending in `\`), or an inline code
// span that does, unless the span is a template: a word in capitals such as
// NAME or FILE, `<...>`, `[...]` or `...` marks a placeholder. The comment
// after a line may state its exit status as `# exits N` (first thing in the
// comment); otherwise it must exit 0.
//
// The lines of one page run in order in one scratch folder, so a page can
// make a file and then read it; the folder holds a link to the repository's
// tests/ (the pages read its fixtures). One test per page.
//
// A ```sh block followed at once (blank lines aside) by a ```text block
// quotes its output: what the block's commands print on stdout, together,
// must be that text, so a figure quoted this way cannot go stale or be typed
// by hand. `bash tests/update_doc_output.sh` rewrites those blocks from the
// commands' output.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace {

namespace fs = std::filesystem;
namespace test = brdflut::test;

struct DocCommand {
    std::string line;  // as quoted, comment removed
    int exit_code = 0;
    int source_line = 0;
    int block = -1;  // index in DocPage::outputs of the block whose output it quotes, or -1
};

// A ```text block that quotes the output of the ```sh block before it:
// lines [first, last) of the page (0-based, the fences excluded).
struct QuotedOutput {
    int first = 0, last = 0;
    std::string indent;  // of the fence (a block in a list item), not part of the text
    std::string text;
};

struct DocPage {
    std::vector<std::string> lines;
    std::vector<DocCommand> commands;
    std::vector<QuotedOutput> outputs;
};

std::string source_text(const std::string& page) {
    std::ifstream in(std::string(BRDFLUT_SOURCE_DIR) + "/" + page);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

bool is_command(const std::string& s) { return starts_with(s, "brdflut ") || starts_with(s, "./build/brdflut "); }

// A code span such as `brdflut generate --preset NAME`: a template, not a
// command line.
bool is_template(const std::string& s) {
    if (s.find("...") != std::string::npos || s.find('<') != std::string::npos || s.find('[') != std::string::npos)
        return true;
    static const std::regex placeholder(R"((^|[\s=,:])[A-Z][A-Z0-9_]+($|[\s=,:]))");
    return std::regex_search(s, placeholder);
}

// Splits off a trailing ` # comment` and reads `exits N` at its start.
DocCommand finish(std::string line, int source_line) {
    DocCommand c;
    c.source_line = source_line;
    const std::size_t hash = line.find(" #");
    if (hash != std::string::npos) {
        static const std::regex status(R"(^\s*exits (\d+))");
        std::smatch m;
        const std::string comment = line.substr(hash + 2);
        if (std::regex_search(comment, m, status)) c.exit_code = std::stoi(m[1]);
        line.erase(hash);
    }
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    c.line = line;
    return c;
}

DocPage read_page(const std::string& page) {
    DocPage p;
    {
        std::istringstream in(source_text(page));
        std::string line;
        while (std::getline(in, line)) p.lines.push_back(line);
    }
    std::string pending;
    int pending_line = 0;
    std::vector<std::size_t> block_commands;  // commands of the current ```sh block
    bool in_block = false, sh = false;
    std::size_t last_sh_end = std::string::npos;  // line of the fence closing the last ```sh block
    for (std::size_t i = 0; i < p.lines.size(); ++i) {
        const std::string& line = p.lines[i];
        const int number = static_cast<int>(i) + 1;
        const std::size_t indent = line.find_first_not_of(' ');
        const std::string body = indent == std::string::npos ? "" : line.substr(indent);
        if (starts_with(body, "```")) {
            if (!in_block) {
                in_block = true;
                sh = body == "```sh";
                if (sh) block_commands.clear();
                if (body == "```text" && last_sh_end != std::string::npos) {
                    bool adjacent = true;
                    for (std::size_t k = last_sh_end + 1; k < i; ++k)
                        if (p.lines[k].find_first_not_of(' ') != std::string::npos) adjacent = false;
                    if (adjacent && !block_commands.empty()) {
                        QuotedOutput q;
                        q.first = static_cast<int>(i) + 1;
                        q.indent = line.substr(0, indent);
                        std::size_t k = i + 1;
                        for (; k < p.lines.size() && !starts_with(p.lines[k].substr(std::min(indent, p.lines[k].size())), "```"); ++k)
                            q.text += (starts_with(p.lines[k], q.indent) ? p.lines[k].substr(indent) : p.lines[k]) + "\n";
                        q.last = static_cast<int>(k);
                        for (std::size_t c : block_commands) p.commands[c].block = static_cast<int>(p.outputs.size());
                        p.outputs.push_back(q);
                    }
                }
            } else {
                in_block = false;
                last_sh_end = sh ? i : std::string::npos;
            }
            continue;
        }
        if (!in_block && !body.empty()) last_sh_end = std::string::npos;
        if (in_block) {
            if (!sh) continue;
            if (pending.empty()) {
                if (!is_command(body)) continue;
                pending_line = number;
                pending = body;
            } else {
                pending += " " + body;
            }
            if (!pending.empty() && pending.back() == '\\') {
                pending.pop_back();
                while (!pending.empty() && pending.back() == ' ') pending.pop_back();
                continue;
            }
            block_commands.push_back(p.commands.size());
            p.commands.push_back(finish(pending, pending_line));
            pending.clear();
            continue;
        }
        // Inline code spans of prose lines.
        std::size_t at = 0;
        while ((at = line.find('`', at)) != std::string::npos) {
            const std::size_t end = line.find('`', at + 1);
            if (end == std::string::npos) break;
            const std::string span = line.substr(at + 1, end - at - 1);
            if (is_command(span) && !is_template(span)) p.commands.push_back(finish(span, number));
            at = end + 1;
        }
    }
    return p;
}

std::vector<DocCommand> page_commands(const std::string& page) { return read_page(page).commands; }

// The pages that quote at least one command line.
std::vector<std::string> pages() {
    std::vector<std::string> out;
    if (!page_commands("README.md").empty()) out.push_back("README.md");
    for (const char* folder : {"docs", "docs/reference"}) {
        std::vector<std::string> here;
        for (const fs::directory_entry& e : fs::directory_iterator(fs::path(BRDFLUT_SOURCE_DIR) / folder))
            if (e.is_regular_file() && e.path().extension() == ".md") {
                const std::string page = std::string(folder) + "/" + e.path().filename().string();
                if (!page_commands(page).empty()) here.push_back(page);
            }
        std::sort(here.begin(), here.end());
        out.insert(out.end(), here.begin(), here.end());
    }
    return out;
}

std::string test_name(const testing::TestParamInfo<std::string>& info) {
    std::string s = info.param;
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return s;
}

class DocCommands : public testing::TestWithParam<std::string> {};

TEST_P(DocCommands, EveryCommandLineRunsWithTheExitStatusItsTextGives) {
    DocPage page = read_page(GetParam());
    ASSERT_FALSE(page.commands.empty());
    test::TempDir dir;
    fs::create_symlink(fs::path(BRDFLUT_SOURCE_DIR) / "tests", dir.path() / "tests");
    std::vector<std::string> printed(page.outputs.size());
    for (const DocCommand& c : page.commands) {
        const std::string args = c.line.substr(c.line.find("brdflut ") + 8);
        const auto start = std::chrono::steady_clock::now();
        const std::string cmd = "cd '" + dir.path().string() + "' && '" + BRDFLUT_CLI + "' " + args + " > '" +
                                (dir / "out.txt") + "' 2> '" + (dir / "err.txt") + "' < /dev/null";
        const int status = std::system(cmd.c_str());
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        std::printf("%s:%d (%.1f s, exit %d): %s\n", GetParam().c_str(), c.source_line, seconds, code,
                    c.line.c_str());
        EXPECT_EQ(code, c.exit_code) << GetParam() << ":" << c.source_line << ": " << c.line << "\n"
                                     << test::read_file(dir / "err.txt");
        if (c.block >= 0) printed[c.block] += test::read_file(dir / "out.txt");
    }
    const bool update = std::getenv("BRDFLUT_UPDATE_DOC_OUTPUT") != nullptr;
    bool changed = false;
    for (std::size_t b = page.outputs.size(); b-- > 0;) {  // from the end: line numbers stay valid
        const QuotedOutput& q = page.outputs[b];
        if (printed[b] == q.text) continue;
        if (update) {
            std::vector<std::string> fresh;
            std::istringstream in(printed[b]);
            for (std::string l; std::getline(in, l);) fresh.push_back(l.empty() ? l : q.indent + l);
            page.lines.erase(page.lines.begin() + q.first, page.lines.begin() + q.last);
            page.lines.insert(page.lines.begin() + q.first, fresh.begin(), fresh.end());
            changed = true;
        } else {
            ADD_FAILURE() << GetParam() << ":" << q.first << ": the quoted output is not what its commands print "
                          << "(bash tests/update_doc_output.sh rewrites it); they print:\n"
                          << printed[b];
        }
    }
    if (changed) {
        std::ofstream out(fs::path(BRDFLUT_SOURCE_DIR) / GetParam());
        for (const std::string& l : page.lines) out << l << "\n";
        std::printf("rewrote the quoted output in %s\n", GetParam().c_str());
    }
}

INSTANTIATE_TEST_SUITE_P(Pages, DocCommands, testing::ValuesIn(pages()), test_name);

TEST(DocCommandPages, IncludeTheReadmeAndTheMainTopicPages) {
    const std::vector<std::string> p = pages();
    for (const char* page : {"README.md", "docs/usage.md", "docs/checking.md", "docs/ltc.md", "docs/shaders.md"})
        EXPECT_NE(std::find(p.begin(), p.end(), page), p.end()) << page;
}

// The reader of the pages: blocks, continuations, comments, statuses and
// templates.
TEST(DocCommandParser, ReadsBlocksSpansStatusesAndSkipsTemplates) {
    const std::vector<DocCommand> c = page_commands("tests/doc_commands_sample.md");
    ASSERT_EQ(c.size(), 6u);
    EXPECT_EQ(c[0].line, "brdflut list");
    EXPECT_EQ(c[0].exit_code, 0);
    EXPECT_EQ(c[1].line, "brdflut compare a.exr --as ggx_dfg --tolerance 1e-4");
    EXPECT_EQ(c[1].exit_code, 1);
    EXPECT_EQ(c[2].line, "./build/brdflut verify ggx_dfg");
    EXPECT_EQ(c[3].line, "brdflut generate ltc_1");
    EXPECT_EQ(c[4].line, "brdflut list --presets");
    EXPECT_EQ(c[5].line, "brdflut generate --help");
    const DocPage p = read_page("tests/doc_commands_sample.md");
    ASSERT_EQ(p.outputs.size(), 1u);
    EXPECT_EQ(p.outputs[0].text, "usage text\nsecond line\n");
    EXPECT_EQ(c[0].block, -1);
    EXPECT_EQ(p.commands[5].block, 0);
    EXPECT_TRUE(is_template("brdflut generate --preset NAME"));
    EXPECT_TRUE(is_template("brdflut compare FILE --as ID"));
    EXPECT_TRUE(is_template("brdflut verify [ID...]"));
    EXPECT_FALSE(is_template("brdflut generate ggx_dfg --size 64 --pixel half"));
}

}  // namespace
