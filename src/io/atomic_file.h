// Writes a file atomically: the data goes to a temporary file in the
// destination folder, which commit() renames over the destination. If
// commit() is not reached (an exception, an interruption), the temporary
// file is removed and the previous destination file is left untouched.
#pragma once

#include <string>

namespace brdflut {

class AtomicFile {
public:
    explicit AtomicFile(std::string path);  // throws RuntimeError if the folder is unusable
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& temp_path() const { return temp_; }
    void commit();  // throws RuntimeError

private:
    std::string path_, temp_;
    bool committed_ = false;
    int slot_ = -1;
};

// Removes every temporary file still registered (for signal handlers:
// async-signal-safe, uses only unlink).
void remove_pending_temporary_files();

}  // namespace brdflut
