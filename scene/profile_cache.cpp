// profile_cache.cpp: see profile_cache.h.
#include "scene/profile_cache.h"

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace st {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMagic = "shadertwin profiles 1\n";

std::optional<fs::path> cache_dir() {
    if (const char* own = std::getenv("SHADERTWIN_CACHE")) {
        if (std::string(own) == "off" || !*own) return std::nullopt;
        return fs::path(own);
    }
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "shadertwin" / "profiles";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "shadertwin" / "profiles";
    return std::nullopt;
}

// FNV-1a: a file name that is the same in every build.
std::string file_name(const std::string& key, const char* extension = ".bin") {
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : key) h = (h ^ c) * 1099511628211ull;
    std::ostringstream s;
    s << std::hex << h << extension;
    return s.str();
}

// Writes through a temporary file and a rename; false (nothing left) on failure.
template <class Write> bool write_atomically(const fs::path& path, Write&& write) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) return false;
    const fs::path tmp = path.string() + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return false;
        write(out);
        if (!out) {
            out.close();
            fs::remove(tmp, ec);
            return false;
        }
    }
    fs::rename(tmp, path, ec);
    if (ec) fs::remove(tmp, ec);
    return !ec;
}

void put(std::ostream& o, uint64_t n) { o.write(reinterpret_cast<const char*>(&n), sizeof n); }
void put(std::ostream& o, const std::vector<double>& v) {
    put(o, uint64_t(v.size()));
    o.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(double)));
}
bool get(std::istream& i, uint64_t& n) { return bool(i.read(reinterpret_cast<char*>(&n), sizeof n)); }
bool get(std::istream& i, std::vector<double>& v, uint64_t expected) {
    uint64_t n = 0;
    if (!get(i, n) || n != expected) return false;
    v.resize(n);
    return bool(i.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(double))));
}

}  // namespace

std::optional<TabulatedProfiles> load_cached_profiles(const std::string& key) {
    const auto dir = cache_dir();
    if (!dir) return std::nullopt;
    std::ifstream in(*dir / file_name(key), std::ios::binary);
    if (!in) return std::nullopt;
    std::string magic(std::string(kMagic).size(), '\0');
    uint64_t key_size = 0, n = 0, dipoles = 0;
    if (!in.read(magic.data(), std::streamsize(magic.size())) || magic != kMagic || !get(in, key_size) || key_size > 65536)
        return std::nullopt;
    std::string stored(key_size, '\0');
    if (!in.read(stored.data(), std::streamsize(key_size)) || stored != key) return std::nullopt;
    TabulatedProfiles t;
    if (!get(in, dipoles) || !get(in, n) || n > (1u << 24)) return std::nullopt;
    t.dipoles = int(dipoles);
    if (!get(in, t.radii, n)) return std::nullopt;
    for (int c = 0; c < 3; ++c)
        if (!get(in, t.R[size_t(c)], n) || !get(in, t.T[size_t(c)], n)) return std::nullopt;
    return t;
}

void store_cached_profiles(const std::string& key, const TabulatedProfiles& t) {
    const auto dir = cache_dir();
    if (!dir) return;
    write_atomically(*dir / file_name(key), [&](std::ofstream& out) {
        out.write(kMagic, std::streamsize(std::string(kMagic).size()));
        put(out, uint64_t(key.size()));
        out.write(key.data(), std::streamsize(key.size()));
        put(out, uint64_t(t.dipoles));
        put(out, uint64_t(t.radii.size()));
        put(out, t.radii);
        for (int c = 0; c < 3; ++c) put(out, t.R[size_t(c)]), put(out, t.T[size_t(c)]);
    });
}

// A record: the magic line, the key's size and the key, then the value.
constexpr const char* kRecordMagic = "shadertwin record 1\n";

std::optional<std::string> load_cached_record(const std::string& key) {
    const auto dir = cache_dir();
    if (!dir) return std::nullopt;
    std::ifstream in(*dir / file_name(key, ".txt"), std::ios::binary);
    if (!in) return std::nullopt;
    std::string magic(std::string(kRecordMagic).size(), '\0');
    uint64_t key_size = 0, value_size = 0;
    if (!in.read(magic.data(), std::streamsize(magic.size())) || magic != kRecordMagic || !get(in, key_size) ||
        key_size > (1u << 20))
        return std::nullopt;
    std::string stored(key_size, '\0');
    if (!in.read(stored.data(), std::streamsize(key_size)) || stored != key) return std::nullopt;
    if (!get(in, value_size) || value_size > (1u << 20)) return std::nullopt;
    std::string value(value_size, '\0');
    if (!in.read(value.data(), std::streamsize(value_size))) return std::nullopt;
    return value;
}

void store_cached_record(const std::string& key, const std::string& value) {
    const auto dir = cache_dir();
    if (!dir) return;
    write_atomically(*dir / file_name(key, ".txt"), [&](std::ofstream& out) {
        out.write(kRecordMagic, std::streamsize(std::string(kRecordMagic).size()));
        put(out, uint64_t(key.size()));
        out.write(key.data(), std::streamsize(key.size()));
        put(out, uint64_t(value.size()));
        out.write(value.data(), std::streamsize(value.size()));
    });
}

}  // namespace st
