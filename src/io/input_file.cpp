#include "io/input_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "brdflut/error.h"

namespace brdflut {
namespace {

std::string kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

}  // namespace

InputFile::InputFile(const std::string& path) : path_(path) {
    // O_NONBLOCK: opening a FIFO that has no writer returns at once instead of
    // waiting for one; the file is refused below before anything is read.
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0) {
        const int e = errno;
        fail(e == ENOENT || e == ENOTDIR ? std::string("no such file") : std::strerror(e));
    }
    struct stat st{};
    if (::fstat(fd_, &st) != 0) fail(std::strerror(errno));
    if (!S_ISREG(st.st_mode)) {
        const std::string kind = kind_of(st.st_mode);
        fail(kind == "not a regular file" ? kind : "not a regular file (" + kind + ")");
    }
    size_ = static_cast<std::uint64_t>(st.st_size);
}

InputFile::~InputFile() {
    if (fd_ >= 0) ::close(fd_);
}

void InputFile::fail(const std::string& why) const { throw RuntimeError("cannot read '" + path_ + "': " + why); }

std::string InputFile::read_at_most(std::uint64_t n) {
    std::string out;
    out.resize(static_cast<std::size_t>(n));
    std::size_t got = 0;
    while (got < out.size()) {
        const ssize_t r = ::pread(fd_, out.data() + got, out.size() - got, static_cast<off_t>(got));
        if (r < 0) {
            if (errno == EINTR) continue;
            fail(std::strerror(errno));
        }
        if (r == 0) break;  // the file shrank since fstat
        got += static_cast<std::size_t>(r);
    }
    out.resize(got);
    return out;
}

std::string InputFile::head(std::size_t n) { return read_at_most(std::min<std::uint64_t>(n, size_)); }

std::string InputFile::read_all(std::uint64_t limit, const std::string& what) {
    if (size_ > limit)
        fail("the file is " + std::to_string(size_) + " bytes; at most " + std::to_string(limit) + " bytes are read for " +
             what);
    return read_at_most(size_);  // a file that grew since fstat is read to its size then
}

}  // namespace brdflut
