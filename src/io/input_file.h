// Opening a file to read as a table: look before reading. The file is opened
// without blocking (a FIFO without a writer does not hang), refused unless it
// is a regular file (FIFOs, devices such as /dev/zero, directories, sockets),
// its first bytes can be looked at before anything else is read, and it is
// read whole only within a size limit, so memory never grows past the limit
// whatever the file claims or holds.
#pragma once

#include <cstdint>
#include <string>

namespace brdflut {

class InputFile {
public:
    // Throws brdflut::RuntimeError "cannot read 'PATH': ..." when the file is
    // missing, unreadable or not a regular file.
    explicit InputFile(const std::string& path);
    ~InputFile();
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    const std::string& path() const { return path_; }
    std::uint64_t size() const { return size_; }
    // The first min(n, size()) bytes.
    std::string head(std::size_t n);
    // The whole file; refused (RuntimeError naming the size and the limit)
    // when it is larger than `limit` bytes, which `what` names ("a binary
    // file", "a source file").
    std::string read_all(std::uint64_t limit, const std::string& what);
    [[noreturn]] void fail(const std::string& why) const;

private:
    std::string path_;
    int fd_ = -1;
    std::uint64_t size_ = 0;
    std::string read_at_most(std::uint64_t n);
};

}  // namespace brdflut
