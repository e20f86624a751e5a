// Errors the library reports. Library code throws; only the command line
// chooses exit codes.
#pragma once

#include <stdexcept>
#include <string>

namespace brdflut {

// Bad input from the caller: names the parameter, the value and what is allowed.
class Error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// A failure while doing the work (an unwritable file, a corrupt input).
class RuntimeError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace brdflut
