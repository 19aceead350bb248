// fuzz_support.h: what the reader targets share. The readers under test
// take a path, so each fuzz input is written to a file of this process's own
// first (in /dev/shm when there is one: no disk traffic at thousands of
// inputs a second); and each reader must accept the input or refuse it with
// a message of ours.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace st::fuzz {

inline std::string write_input(const uint8_t* data, size_t size, const std::string& extension) {
    static const std::string dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    const std::string path = dir + "/shadertwin-fuzz-" + std::to_string(getpid()) + extension;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) __builtin_trap();
    if (size) std::fwrite(data, 1, size, f);
    std::fclose(f);
    return path;
}

// Runs `read`. A refusal must be a std::exception with a message;
// nlohmann's own exceptions escaping a reader mean a field went unchecked
// (the user would read "[json.exception.type_error.302] ..."), and
// std::bad_alloc that a size went unchecked: those, and an empty message,
// abort, which the fuzzer reports.
template <class Read>
void expect_accept_or_refuse(Read&& read) {
    try {
        read();
    } catch (const nlohmann::json::exception&) {
        std::abort();
    } catch (const std::bad_alloc&) {
        std::abort();
    } catch (const std::exception& e) {
        if (!*e.what()) std::abort();
    }
}

}  // namespace st::fuzz
