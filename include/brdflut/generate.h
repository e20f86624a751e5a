// Fills a table by evaluating every texel in parallel (oneTBB). The result
// does not depend on the number of threads.
#pragma once

#include <cstddef>
#include <functional>

#include "brdflut/catalogue.h"
#include "brdflut/table.h"

namespace brdflut {

struct GenerateOptions {
    int threads = 0;  // 0: all hardware threads
    // Called from worker threads, one call at a time, with texels done and total.
    std::function<void(std::size_t, std::size_t)> progress;
};

Table generate(const TableDefinition& def, const TableSettings& settings,
               const GenerateOptions& options = {});

// Runs fn(i) for every i in [0, n) on up to `threads` worker threads (0: all).
// fn must write only to its own slot of any shared output.
void parallel_for_index(std::size_t n, int threads, const std::function<void(std::size_t)>& fn);

}  // namespace brdflut
