// input_error.h: the error for bad user input (scene files, options). The
// command line prints its message as one line and exits with code 2.
#pragma once

#include <stdexcept>

namespace st {

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace st
