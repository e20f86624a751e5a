#include "io/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <filesystem>
#include <unistd.h>

#include "brdflut/error.h"

namespace brdflut {
namespace {
// A fixed registry of temporary paths that a signal handler may unlink.
constexpr int kSlots = 64;
constexpr std::size_t kPathMax = 4096;
std::array<std::atomic<bool>, kSlots> g_used{};
std::array<std::array<char, kPathMax>, kSlots> g_paths{};

int register_temp(const std::string& p) {
    if (p.size() + 1 > kPathMax) return -1;
    for (int i = 0; i < kSlots; ++i) {
        bool expected = false;
        if (g_used[static_cast<std::size_t>(i)].load() == false) {
            std::memcpy(g_paths[static_cast<std::size_t>(i)].data(), p.c_str(), p.size() + 1);
            if (g_used[static_cast<std::size_t>(i)].compare_exchange_strong(expected, true)) return i;
        }
    }
    return -1;
}
}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
    namespace fs = std::filesystem;
    const fs::path p(path_);
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    std::string name = ".";  // built in steps: GCC 12 warns (-Wrestrict) on "." + string
    name += p.filename().string();
    name += ".tmp-XXXXXX";
    std::string pattern = (dir / name).string();
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0)
        throw RuntimeError("cannot write '" + path_ + "': cannot create a file in '" +
                           dir.string() + "': " + std::strerror(errno));
    ::close(fd);
    temp_ = pattern;
    slot_ = register_temp(temp_);
}

AtomicFile::~AtomicFile() {
    if (!committed_) ::unlink(temp_.c_str());
    if (slot_ >= 0) g_used[static_cast<std::size_t>(slot_)].store(false);
}

void AtomicFile::commit() {
    // mkstemp creates the file with mode 0600; give it the usual mode.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::chmod(temp_.c_str(), 0666 & ~mask);
    if (std::rename(temp_.c_str(), path_.c_str()) != 0)
        throw RuntimeError("cannot write '" + path_ + "': " + std::strerror(errno));
    committed_ = true;
}

void remove_pending_temporary_files() {
    for (int i = 0; i < kSlots; ++i)
        if (g_used[static_cast<std::size_t>(i)].load()) ::unlink(g_paths[static_cast<std::size_t>(i)].data());
}

}  // namespace brdflut
