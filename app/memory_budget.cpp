// memory_budget.cpp: see memory_budget.h.
#include "app/memory_budget.h"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "scene/scene.h"

namespace st {

namespace {

constexpr uint64_t kMiB = uint64_t(1) << 20;

// Measured on Debian 12's Mesa 22.3 (llvmpipe, LLVM 15) and OpenImageIO
// 2.4: the resident memory of rendering a one-triangle scene on both
// backends, less what was resident before the GL context was made.
constexpr uint64_t kRuntimeBaseline = 200 * kMiB;
// Address space that the libraries, Mesa, LLVM and the worker threads map
// beyond what becomes resident (checked against `ulimit -v` only): the
// smallest limit under which a comparison runs, less its peak resident
// memory, was at most 1.0 GB at 256x256 and at 2048x2048.
constexpr uint64_t kAddressSpaceOverhead = 1000 * kMiB;

// Bytes per pixel of every image drawn (the frame's and each target
// texel), held at once at the peak: the CPU's framebuffer and depth, its
// read-back image; llvmpipe's RGBA32F attachment, depth and read-back; the
// EXR and PNG being written; for compare, both sides, the coverage pass
// and the heat map. Measured slopes (thin slab, 1024^2 to 2048^2): 40, 52
// and 119 bytes; these leave about a fifth to spare.
double bytes_per_pixel(MemoryUse use) {
    switch (use) {
        case MemoryUse::RenderCpu: return 48;
        case MemoryUse::RenderGl: return 64;
        case MemoryUse::BothBackends: return 112;
        case MemoryUse::Compare: return 144;
    }
    return 144;
}

// What a command keeps of each scene it has rendered while it renders the
// next: llvmpipe's compiled shader variants and the allocator's free lists.
// Comparing all 239 built-in scenes in one run grew the resident memory by
// 0.9 MiB a scene.
constexpr uint64_t kRetainedPerScene = 2 * kMiB;

int backends(MemoryUse use) { return use == MemoryUse::RenderCpu || use == MemoryUse::RenderGl ? 1 : 2; }

uint64_t status_field(const char* name) {  // /proc/self/status, in bytes
    std::ifstream in("/proc/self/status");
    const std::string key = std::string(name) + ":";
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key, 0) == 0) return uint64_t(std::stoull(line.substr(key.size()))) * 1024;
    return 0;
}

uint64_t meminfo_available() {
    std::ifstream in("/proc/meminfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("MemAvailable:", 0) == 0) return uint64_t(std::stoull(line.substr(13))) * 1024;
    return UINT64_MAX;
}

// The cgroup v2 limit of this process, less what the group uses now.
uint64_t cgroup_headroom() {
    std::ifstream cg("/proc/self/cgroup");
    std::string line, path;
    while (std::getline(cg, line))
        if (line.rfind("0::", 0) == 0) path = line.substr(3);
    if (path.empty()) return UINT64_MAX;
    std::ifstream max_in("/sys/fs/cgroup" + path + "/memory.max"), cur_in("/sys/fs/cgroup" + path + "/memory.current");
    std::string max_text;
    uint64_t current = 0;
    if (!(max_in >> max_text) || max_text == "max" || !(cur_in >> current)) return UINT64_MAX;
    const uint64_t limit = std::stoull(max_text);
    return limit > current ? limit - current : 0;
}

}  // namespace

uint64_t estimate_memory(const Frame& frame, MemoryUse use) {
    double pixels = 0, texels = 0, vertices = 0;
    for (const Pass& pass : frame.passes) {
        if (pass.target.empty()) pixels = double(pass.width) * pass.height;
        for (const DrawCall& d : pass.draws) {
            vertices += double(d.indices.size());
            for (const Texture& t : d.textures) {
                if (!t.target.empty()) continue;  // a render target, counted below
                double level = double(t.width) * t.height, sum = 0;
                for (int l = 0; l < t.level_count(); ++l, level /= 4) sum += level;
                texels += sum * t.faces();
            }
        }
    }
    for (const RenderTarget& t : frame.targets)
        for (int l = 0; l < t.levels; ++l)
            pixels += double(std::max(1, t.width >> l)) * double(std::max(1, t.height >> l));
    // Each backend keeps a float copy of every texel (16 bytes; llvmpipe's
    // upload and its mip levels, our sampler's) and per vertex its shaded
    // outputs and window position (256 bytes is the CPU's worst case).
    const double added = pixels * bytes_per_pixel(use) + backends(use) * (texels * 32 + vertices * 256);
    return resident_bytes() + kRuntimeBaseline + uint64_t(std::ceil(added));
}

MemoryBudget memory_budget(uint64_t max_memory) {
    const uint64_t now = resident_bytes();
    MemoryBudget b{UINT64_MAX, ""};
    auto consider = [&](uint64_t resident, const char* source) {
        if (resident < b.resident) b = {resident, source};
    };
    if (max_memory) consider(max_memory, "--max-memory");
    // The others are what may still be taken: add what is resident now.
    const uint64_t available = meminfo_available(), cgroup = cgroup_headroom();
    if (available != UINT64_MAX) consider(now + available, "the machine's available memory (MemAvailable)");
    if (cgroup != UINT64_MAX) consider(now + cgroup, "the cgroup's memory.max");
    rlimit as{};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
        consider(as.rlim_cur > kAddressSpaceOverhead ? as.rlim_cur - kAddressSpaceOverhead : 0,
                 "the address-space limit (ulimit -v, less 1000 MiB of mappings)");
    }
    return b;
}

std::vector<uint64_t> check_memory(const std::vector<Scene>& scenes, MemoryUse use, uint64_t max_memory) {
    const MemoryBudget budget = memory_budget(max_memory);
    std::vector<uint64_t> estimates;
    for (const Scene& scene : scenes) {
        const uint64_t retained = kRetainedPerScene * estimates.size();  // of the scenes before it
        const uint64_t need = estimates.emplace_back(estimate_memory(scene.frame, use) + retained);
        if (need > budget.resident)
            throw std::runtime_error(scene.name + ": needs an estimated " + memory_figure(need) + " of memory, more than the " +
                                     memory_figure(budget.resident) + " allowed by " + budget.source +
                                     "; render it smaller, or raise the limit");
    }
    return estimates;
}

uint64_t parse_memory_size(const std::string& text) {
    size_t used = 0;
    double value = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    std::string unit = text.substr(used);
    if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b')) unit.pop_back();
    if (unit.size() == 2 && unit[1] == 'i') unit.pop_back();
    double scale = 0;
    if (unit.empty()) scale = 1;
    else if (unit == "K" || unit == "k") scale = 1024.0;
    else if (unit == "M" || unit == "m") scale = 1024.0 * 1024;
    else if (unit == "G" || unit == "g") scale = 1024.0 * 1024 * 1024;
    else if (unit == "T" || unit == "t") scale = 1024.0 * 1024 * 1024 * 1024;
    const double bytes = value * scale;
    if (used == 0 || scale == 0 || !(bytes >= 1) || !(bytes < 1e18))
        throw std::invalid_argument("--max-memory takes a size such as 4G, 512M or 800000K, not '" + text + "'");
    return uint64_t(bytes);
}

std::string memory_figure(uint64_t bytes) {
    char text[32];
    if (bytes >= (uint64_t(1) << 30)) std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(1 << 30));
    else std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / double(kMiB));
    return text;
}

uint64_t resident_bytes() { return status_field("VmRSS"); }
uint64_t peak_resident_bytes() { return status_field("VmHWM"); }

void reset_peak_resident() {
    std::ofstream out("/proc/self/clear_refs");
    out << "5";  // resets VmHWM to the current VmRSS (Linux 4.0 and later)
}

}  // namespace st
