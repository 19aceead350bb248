// photon_rng.h: the random numbers of the Monte Carlo tracer. xoshiro256**
// (Blackman and Vigna), seeded through splitmix64 from (seed, stream), so
// every chunk of photons has its own stream and a run does not depend on how
// chunks are spread over threads.
#pragma once

#include <cstdint>

namespace st::optics {

class PhotonRng {
public:
    PhotonRng(uint64_t seed, uint64_t stream) {
        uint64_t x = seed * 0x9e3779b97f4a7c15ull ^ (stream + 0x632be59bd9b4e019ull);
        for (uint64_t& s : s_) s = splitmix64(x);
    }

    // Uniform in (0, 1]: never 0, so -log(u) is finite.
    double uniform() { return (double(next() >> 11) + 1.0) * 0x1.0p-53; }

private:
    static uint64_t splitmix64(uint64_t& x) {
        uint64_t z = (x += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    uint64_t next() {
        const uint64_t result = rotl(s_[1] * 5, 7) * 9;
        const uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }
    uint64_t s_[4];
};

}  // namespace st::optics
