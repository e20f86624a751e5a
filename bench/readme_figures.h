// The README's performance figures, rendered from the benchmarks' own
// output so that they cannot be typed in by hand or go stale unnoticed.
//
// brdflut_dfg_race and brdflut_table_report print machine-readable lines,
// a keyword then key=value fields:
//   race     table size quality samples rounds hardware_threads
//   time     program threads median_s min_s max_s
//   ratio    threads ggx_dfg_over_karis_float ggx_dfg_over_karis_double
//   accuracy program evaluations_per_texel max_error rms_error [error_bound]
//   table    id threads wall_s cpu_s evaluations_per_texel max_error_stored max_error error_bound uncovered
// render_block() turns them into the Markdown between kBegin and kEnd in
// README.md, followed by the lines themselves, so a test can re-render the
// block from the lines it holds and compare (bench/update_readme.sh rewrites
// the block; tests/test_readme.cpp checks it).
#pragma once

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace bench {

inline const std::string kBegin =
    "<!-- BEGIN benchmark figures: written by bench/update_readme.sh from the output below; do not edit -->";
inline const std::string kEnd = "<!-- END benchmark figures -->";

struct Record {
    std::string kind;
    std::vector<std::pair<std::string, std::string>> fields;  // in printed order

    bool has(const std::string& key) const {
        for (const auto& [k, v] : fields)
            if (k == key) return true;
        return false;
    }
    const std::string& at(const std::string& key) const {
        for (const auto& [k, v] : fields)
            if (k == key) return v;
        throw std::runtime_error("benchmark line '" + line() + "' has no field '" + key + "'");
    }
    double number(const std::string& key) const {
        const std::string& v = at(key);
        std::size_t used = 0;
        double x = 0.0;
        try {
            x = std::stod(v, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != v.size() || !std::isfinite(x))
            throw std::runtime_error("field " + key + "=" + v + " of '" + line() + "' is not a finite number");
        return x;
    }
    std::string line() const {
        std::string s = kind;
        for (const auto& [k, v] : fields) s += " " + k + "=" + v;
        return s;
    }
};

inline bool is_record_kind(const std::string& w) {
    return w == "race" || w == "time" || w == "ratio" || w == "accuracy" || w == "table";
}

// The machine-readable lines of a benchmark output: those that start with a
// record's keyword in the first column (other lines are skipped).
// Throws on a line of a known kind whose fields are not key=value.
inline std::vector<Record> parse_records(const std::string& text) {
    std::vector<Record> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        // A record starts at the beginning of its line (the programs'
        // indented human-readable lines may start with the same words).
        if (line.empty() || line[0] == ' ' || line[0] == '\t') continue;
        std::istringstream words(line);
        std::string w;
        if (!(words >> w) || !is_record_kind(w)) continue;
        Record r{w, {}};
        while (words >> w) {
            const std::size_t eq = w.find('=');
            if (eq == std::string::npos || eq == 0 || eq + 1 == w.size())
                throw std::runtime_error("benchmark line '" + line + "': '" + w + "' is not key=value");
            r.fields.emplace_back(w.substr(0, eq), w.substr(eq + 1));
        }
        out.push_back(std::move(r));
    }
    return out;
}

inline std::string format(const char* fmt, double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, x);
    return buf;
}

// The program names of brdflut_dfg_race and what they are.
inline std::string race_program_label(const std::string& program, const std::string& samples) {
    if (program == "ggx_dfg") return "`ggx_dfg` 128x128, quadrature, default quality";
    if (program == "karis_float")
        return "Karis 2013 / Filament DFG estimator, " + samples + " Hammersley samples, float";
    if (program == "karis_double")
        return "the same estimator in double";
    throw std::runtime_error("unknown race program '" + program + "'");
}

// The Markdown of the figures (without the markers), then the lines it was
// made from. Throws when a figure it needs is missing.
inline std::string render_block(const std::vector<Record>& records) {
    const Record* race = nullptr;
    std::map<std::pair<std::string, int>, const Record*> times;
    std::map<int, const Record*> ratios;
    std::vector<const Record*> accuracy, tables;
    for (const Record& r : records) {
        if (r.kind == "race") race = &r;
        else if (r.kind == "time") times[{r.at("program"), static_cast<int>(r.number("threads"))}] = &r;
        else if (r.kind == "ratio") ratios[static_cast<int>(r.number("threads"))] = &r;
        else if (r.kind == "accuracy") accuracy.push_back(&r);
        else if (r.kind == "table") tables.push_back(&r);
    }
    if (!race) throw std::runtime_error("no 'race' line (brdflut_dfg_race output)");
    if (accuracy.empty()) throw std::runtime_error("no 'accuracy' lines (brdflut_dfg_race output)");
    std::ostringstream md;
    md << "`brdflut_dfg_race`: " << race->at("table") << " " << race->at("size") << " at quality "
       << race->at("quality") << " against the " << race->at("samples")
       << "-sample estimator engines ship, back to back in one process, median wall time of "
       << race->at("rounds") << " rounds (" << race->at("hardware_threads")
       << " hardware threads); errors of the stored float values against `--quality reference`:\n\n";
    md << "| run | 1 thread | 2 threads | evaluations per texel | largest error | rms error |\n";
    md << "|---|---|---|---|---|---|\n";
    for (const Record* a : accuracy) {
        const std::string& p = a->at("program");
        md << "| " << race_program_label(p, race->at("samples"));
        for (int threads : {1, 2}) {
            const auto it = times.find({p, threads});
            if (it == times.end())
                throw std::runtime_error("no 'time' line for " + p + " on " + std::to_string(threads) + " thread(s)");
            md << " | " << format("%.3f s", it->second->number("median_s"));
        }
        md << " | " << format("%.0f", a->number("evaluations_per_texel")) << " | "
           << format("%.1e", a->number("max_error")) << " | " << format("%.1e", a->number("rms_error")) << " |\n";
    }
    md << "| wall time of `ggx_dfg` / the float estimator";
    for (int threads : {1, 2}) {
        const auto it = ratios.find(threads);
        if (it == ratios.end()) throw std::runtime_error("no 'ratio' line for " + std::to_string(threads) + " thread(s)");
        md << " | " << format("%.2f", it->second->number("ggx_dfg_over_karis_float"));
    }
    md << " | | | |\n";
    if (!tables.empty()) {
        int shown = 0, covered = 0;
        for (const Record* t : tables)
            if (t->number("evaluations_per_texel") > 0.0) {
                ++shown;
                if (t->at("uncovered").rfind("0/", 0) == 0 || t->at("uncovered") == "0") ++covered;
            }
        md << "\n`brdflut_table_report --no-mc`: the tables whose integrals count their evaluations, "
              "at default settings, threads: "
           << tables.front()->at("threads")
           << "; wall time per table, errors against `--quality reference`; `uncovered` counts the values whose "
              "own error estimate does not cover their difference to the reference (none in "
           << covered << " of these " << shown << " tables):\n\n";
        md << "| table | wall | evaluations per texel | largest error (stored float) | largest error (computed) "
              "| `error_bound` | uncovered |\n";
        md << "|---|---|---|---|---|---|---|\n";
        for (const Record* t : tables) {
            if (t->number("evaluations_per_texel") <= 0.0) continue;
            md << "| `" << t->at("id") << "` | " << format("%.3f s", t->number("wall_s")) << " | "
               << format("%.0f", t->number("evaluations_per_texel")) << " | "
               << format("%.1e", t->number("max_error_stored")) << " | " << format("%.1e", t->number("max_error"))
               << " | " << format("%.1e", t->number("error_bound")) << " | " << t->at("uncovered") << " |\n";
        }
    }
    md << "\n<details><summary>The benchmark output these figures are rendered from</summary>\n\n```text\n";
    for (const Record& r : records) md << r.line() << "\n";
    md << "```\n\n</details>\n";
    return md.str();
}

// The text between the markers (exclusive, without the newline after
// kBegin); throws when they are missing or out of order.
inline std::string extract_block(const std::string& readme, std::size_t* begin = nullptr,
                                 std::size_t* end = nullptr) {
    const std::size_t b = readme.find(kBegin);
    if (b == std::string::npos) throw std::runtime_error("README has no line '" + kBegin + "'");
    const std::size_t body = b + kBegin.size() + 1;
    const std::size_t e = readme.find(kEnd, body);
    if (e == std::string::npos) throw std::runtime_error("README has no line '" + kEnd + "' after the begin marker");
    if (readme.find(kBegin, body) != std::string::npos) throw std::runtime_error("README has two begin markers");
    if (begin) *begin = body;
    if (end) *end = e;
    return readme.substr(body, e - body);
}

// The README with the block between the markers replaced.
inline std::string replace_block(const std::string& readme, const std::string& block) {
    std::size_t b = 0, e = 0;
    extract_block(readme, &b, &e);
    return readme.substr(0, b) + block + readme.substr(e);
}

}  // namespace bench
