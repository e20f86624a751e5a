// Results that the tables generated in one process share: the GGX split
// sums that ggx_albedo takes from ggx_dfg, the LTC fits and error reports
// that ltc_1, ltc_ggx_error and hdrp_ltc_ggx take from one another.
//
// Keyed by the exact bits of the arguments of a deterministic computation,
// so a hit returns bit for bit what a fresh computation would: a cache only
// avoids recomputing, it never changes a value, whatever the thread count or
// the other tables generated. Sharded to keep lock contention low; bounded
// (beyond the bound, values are simply recomputed). clear_shared_results()
// (catalogue.h) empties every cache of this kind.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <unordered_map>

namespace brdflut::tables {

// Registers a cache's clear function with clear_shared_results(); the
// returned id unregisters it.
std::size_t register_shared_results(std::function<void()> clear);
void unregister_shared_results(std::size_t id);

template <std::size_t K, class Value>
class SharedResults {
public:
    using Key = std::array<std::uint64_t, K>;

    // At most max_entries values (rounded up to a multiple of the shard
    // count); a full shard stops caching.
    explicit SharedResults(std::size_t max_entries)
        : max_per_shard_((max_entries + kShards - 1) / kShards), id_(register_shared_results([this] { clear(); })) {}
    ~SharedResults() { unregister_shared_results(id_); }
    SharedResults(const SharedResults&) = delete;
    SharedResults& operator=(const SharedResults&) = delete;

    // The value of key; compute() makes it when it is not cached. *computed
    // tells whether this call computed it (false: taken from an earlier call).
    template <class F>
    Value get(const Key& key, F&& compute, bool* computed = nullptr) {
        Shard& shard = shards_[Hash{}(key) % kShards];
        if (computed) *computed = false;
        {
            const std::lock_guard<std::mutex> lock(shard.mutex);
            const auto it = shard.map.find(key);
            if (it != shard.map.end()) return it->second;
        }
        if (computed) *computed = true;
        Value v = compute();
        const std::lock_guard<std::mutex> lock(shard.mutex);
        if (shard.map.size() < max_per_shard_) shard.map.emplace(key, v);
        return v;
    }

    void clear() {
        for (Shard& shard : shards_) {
            const std::lock_guard<std::mutex> lock(shard.mutex);
            shard.map.clear();
        }
    }

private:
    struct Hash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = 0x9e3779b97f4a7c15ULL;
            for (std::uint64_t d : k) {
                h ^= d + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
                h *= 0xbf58476d1ce4e5b9ULL;
                h ^= h >> 31;
            }
            return static_cast<std::size_t>(h);
        }
    };
    struct Shard {
        std::mutex mutex;
        std::unordered_map<Key, Value, Hash> map;
    };
    static constexpr std::size_t kShards = 64;
    std::size_t max_per_shard_;
    std::size_t id_;
    std::array<Shard, kShards> shards_;
};

// A key word from a double (its exact bits) or an enumerator.
inline std::uint64_t key_bits(double d) { return std::bit_cast<std::uint64_t>(d); }
template <class E>
std::uint64_t key_enum(E e) {
    return static_cast<std::uint64_t>(e);
}

}  // namespace brdflut::tables
