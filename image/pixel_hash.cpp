// pixel_hash.cpp: see pixel_hash.h.
#include "image/pixel_hash.h"

#include <cstdint>

#include <nettle/sha1.h>

namespace st {

std::string sha1_pixel_hash(const float* rgba, int width, int height) {
    sha1_ctx ctx;
    sha1_init(&ctx);
    const size_t bytes = size_t(width > 0 ? width : 0) * size_t(height > 0 ? height : 0) * 4 * sizeof(float);
    sha1_update(&ctx, bytes, reinterpret_cast<const uint8_t*>(rgba));
    uint8_t digest[SHA1_DIGEST_SIZE];
    sha1_digest(&ctx, SHA1_DIGEST_SIZE, digest);
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string out;
    for (uint8_t b : digest) {
        out += kHex[b >> 4];
        out += kHex[b & 15];
    }
    return out;
}

}  // namespace st
