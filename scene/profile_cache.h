// profile_cache.h: tabulated diffusion profiles kept on disk between
// processes, for the materials whose profiles take seconds to build (the
// layered stack, Monte Carlo). One file per material under
// $SHADERTWIN_CACHE, else $XDG_CACHE_HOME/shadertwin/profiles, else
// ~/.cache/shadertwin/profiles; SHADERTWIN_CACHE=off turns it off. A file
// holds its whole key (every parameter, to 17 digits, and the format's
// version), and is used only when the key matches; it is written through a
// temporary file and renamed, so a reader never sees half of one.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace st {

struct TabulatedProfiles {
    std::vector<double> radii;                  // mm, increasing
    std::array<std::vector<double>, 3> R, T;    // per mm^2, per channel, at radii
    int dipoles = 0;
};

std::optional<TabulatedProfiles> load_cached_profiles(const std::string& key);
// Best effort: a cache that cannot be written is skipped without a word.
void store_cached_profiles(const std::string& key, const TabulatedProfiles& profiles);

// A short text kept the same way under its key (a scene's resolved
// `quality: auto`, app/quality/profile_quality.h).
std::optional<std::string> load_cached_record(const std::string& key);
void store_cached_record(const std::string& key, const std::string& value);

}  // namespace st
