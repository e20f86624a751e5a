// Rewrites the benchmark figures of a page (docs/performance.md) from benchmark output.
//
//   brdflut_readme_figures PAGE.md OUTPUT...   (OUTPUT: files, or - for stdin)
//
// The outputs of brdflut_dfg_race and brdflut_table_report are read in the
// order given; their machine-readable lines are rendered by
// readme_figures.h into the block between its markers (see
// bench/update_readme.sh, which runs the benchmarks and this).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "readme_figures.h"

namespace {

std::string read_all(std::istream& in) {
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: brdflut_readme_figures PAGE.md OUTPUT...\n");
        return 2;
    }
    try {
        std::string output;
        for (int a = 2; a < argc; ++a) {
            const std::string name = argv[a];
            if (name == "-") {
                output += read_all(std::cin);
                continue;
            }
            std::ifstream f(name);
            if (!f) throw std::runtime_error("cannot read benchmark output '" + name + "'");
            output += read_all(f);
        }
        const std::string block = bench::render_block(bench::parse_records(output));
        std::ifstream in(argv[1]);
        if (!in) throw std::runtime_error(std::string("cannot read '") + argv[1] + "'");
        const std::string readme = bench::replace_block(read_all(in), block);
        in.close();
        std::ofstream out(argv[1], std::ios::trunc);
        out << readme;
        if (!out) throw std::runtime_error(std::string("cannot write '") + argv[1] + "'");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "brdflut_readme_figures: %s\n", e.what());
        return 1;
    }
    return 0;
}
