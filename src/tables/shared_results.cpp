#include "tables/shared_results.h"

#include <vector>

#include "brdflut/catalogue.h"

namespace brdflut {
namespace tables {
namespace {
struct Clearers {
    std::mutex mutex;
    std::vector<std::function<void()>> list;
};
Clearers& clearers() {
    static Clearers c;
    return c;
}
}  // namespace

void register_shared_results(std::function<void()> clear) {
    Clearers& c = clearers();
    const std::lock_guard<std::mutex> lock(c.mutex);
    c.list.push_back(std::move(clear));
}
}  // namespace tables

void clear_shared_results() {
    tables::Clearers& c = tables::clearers();
    const std::lock_guard<std::mutex> lock(c.mutex);
    for (const auto& clear : c.list) clear();
}

}  // namespace brdflut
