// The only place that runs texels in parallel. Each texel is written to its
// own slot, so the values do not depend on scheduling or thread count.
#include "brdflut/generate.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/info.h>
#include <oneapi/tbb/parallel_for.h>

#include <atomic>
#include <mutex>

#include "brdflut/error.h"

namespace brdflut {

Table generate(const TableDefinition& def, const TableSettings& settings,
               const GenerateOptions& options) {
    validate_settings(def, settings);
    if (options.threads < 0)
        throw Error("--threads " + std::to_string(options.threads) +
                    " is out of range; allowed: 0 (all) or more");
    PreparedTable prepared = def.prepare(settings);

    Table t;
    t.id = def.id;
    t.axes = settings.axes;
    t.channel_map = settings.channel_map;
    if (t.channel_map.empty()) {
        t.channels = def.channels;
    } else {
        for (const auto& sum : t.channel_map) {
            std::string meaning;
            for (int c : sum) meaning += (meaning.empty() ? "" : " + ") + def.channels[static_cast<std::size_t>(c)];
            t.channels.push_back(meaning);
        }
    }
    t.model = prepared.model;
    t.method = prepared.method;
    // Every deterministic table records the quality it was asked for (closed
    // forms ignore it).
    if (settings.method == Method::quadrature) t.method["quality"] = to_string(settings.quality);
    t.options = settings.params;
    const std::size_t texels = t.texel_count();
    const std::size_t nc = t.channels.size();
    t.values.assign(texels * nc, 0.0);
    t.errors.assign(texels * nc, 0.0);

    // Axis values of every storage position, computed once, and where each
    // storage axis goes among the evaluator's coordinates (definition order).
    std::vector<std::vector<double>> axis_values;
    for (const Axis& a : t.axes) {
        std::vector<double> v(static_cast<std::size_t>(a.count));
        for (int i = 0; i < a.count; ++i) v[static_cast<std::size_t>(i)] = a.value(i);
        axis_values.push_back(std::move(v));
    }
    const std::vector<int> order = definition_axis_order(def, settings);

    std::atomic<std::size_t> done{0};
    std::atomic<long long> evaluations{0};
    std::mutex progress_mutex;
    const TexelEvaluator& eval = *prepared.evaluator;
    const auto& map = t.channel_map;
    auto body = [&](const oneapi::tbb::blocked_range<std::size_t>& r) {
        long long work = 0;
        for (std::size_t k = r.begin(); k != r.end(); ++k) {
            double coords[3] = {0.0, 0.0, 0.0};
            std::size_t rest = k;
            for (std::size_t a = 0; a < axis_values.size(); ++a) {
                const std::size_t n = axis_values[a].size();
                coords[order[a]] = axis_values[a][rest % n];
                rest /= n;
            }
            const TexelValue v = eval.evaluate(coords, k);
            for (std::size_t c = 0; c < nc; ++c) {
                if (map.empty()) {
                    t.values[k * nc + c] = v.value[c];
                    t.errors[k * nc + c] = v.error[c];
                    continue;
                }
                // A sum of channels: its error is bounded by the sum of theirs.
                double value = 0.0, error = 0.0;
                for (int tc : map[c]) {
                    value += v.value[static_cast<std::size_t>(tc)];
                    error += v.error[static_cast<std::size_t>(tc)];
                }
                t.values[k * nc + c] = value;
                t.errors[k * nc + c] = error;
            }
            work += v.evaluations;
        }
        evaluations.fetch_add(work, std::memory_order_relaxed);
        const std::size_t now = done.fetch_add(r.size()) + r.size();
        if (options.progress) {
            std::unique_lock<std::mutex> lock(progress_mutex, std::try_to_lock);
            if (lock.owns_lock()) options.progress(now, texels);
        }
    };

    const int threads =
        options.threads > 0 ? options.threads
                            : static_cast<int>(oneapi::tbb::info::default_concurrency());
    oneapi::tbb::global_control limit(oneapi::tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(threads));
    oneapi::tbb::parallel_for(oneapi::tbb::blocked_range<std::size_t>(0, texels, 1), body);
    if (options.progress) options.progress(texels, texels);
    t.evaluations = evaluations.load();
    if (prepared.finish) prepared.finish(t);
    return t;
}

void parallel_for_index(std::size_t n, int threads, const std::function<void(std::size_t)>& fn) {
    const int t = threads > 0 ? threads : static_cast<int>(oneapi::tbb::info::default_concurrency());
    oneapi::tbb::global_control limit(oneapi::tbb::global_control::max_allowed_parallelism,
                                      static_cast<std::size_t>(t));
    oneapi::tbb::parallel_for(oneapi::tbb::blocked_range<std::size_t>(0, n, 1),
                              [&](const oneapi::tbb::blocked_range<std::size_t>& r) {
                                  for (std::size_t i = r.begin(); i != r.end(); ++i) fn(i);
                              });
}

}  // namespace brdflut
