// png_structure.cpp: see png_structure.h. The layout is the PNG
// specification's: an 8-byte signature, then chunks of a 4-byte big-endian
// length, a 4-byte type, the data and a 4-byte CRC, the last one IEND.
#include "image/png_structure.h"

#include <algorithm>
#include <cstdint>
#include <fstream>

namespace st {

std::string png_structure_error(const std::string& path) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::ifstream in(path, std::ios::binary);
    unsigned char head[8];
    if (!in.read(reinterpret_cast<char*>(head), 8) || !std::equal(head, head + 8, kSignature)) return {};
    in.seekg(0, std::ios::end);
    const uint64_t size = uint64_t(in.tellg());
    uint64_t at = 8;
    for (int chunks = 0;; ++chunks) {
        unsigned char header[8];
        in.seekg(std::streamoff(at));
        if (at + 12 > size || !in.read(reinterpret_cast<char*>(header), 8))
            return "the PNG file ends after " + std::to_string(chunks) + " chunks, without IEND (truncated)";
        const uint64_t length = uint64_t(header[0]) << 24 | uint64_t(header[1]) << 16 | uint64_t(header[2]) << 8 | header[3];
        std::string type(reinterpret_cast<const char*>(header + 4), 4);
        for (char& c : type)
            if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'))) return "the PNG file has a corrupt chunk header";
        if (length > 0x7FFFFFFF || at + 12 + length > size)
            return "the PNG file ends inside its " + type + " chunk (truncated)";
        if (type == "IEND") return {};
        at += 12 + length;
    }
}

}  // namespace st
