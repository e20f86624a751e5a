#include "tables/shared_results.h"

#include <map>

#include "brdflut/catalogue.h"

namespace brdflut {
namespace tables {
namespace {
struct Clearers {
    std::mutex mutex;
    std::map<std::size_t, std::function<void()>> list;
    std::size_t next = 0;
};
Clearers& clearers() {
    static Clearers c;
    return c;
}
}  // namespace

std::size_t register_shared_results(std::function<void()> clear) {
    Clearers& c = clearers();
    const std::lock_guard<std::mutex> lock(c.mutex);
    c.list.emplace(c.next, std::move(clear));
    return c.next++;
}

void unregister_shared_results(std::size_t id) {
    Clearers& c = clearers();
    const std::lock_guard<std::mutex> lock(c.mutex);
    c.list.erase(id);
}
}  // namespace tables

void clear_shared_results() {
    tables::Clearers& c = tables::clearers();
    const std::lock_guard<std::mutex> lock(c.mutex);
    for (const auto& [id, clear] : c.list) clear();
}

}  // namespace brdflut
