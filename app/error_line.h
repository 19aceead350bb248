// error_line.h: an error message as the one line a command prints on
// stderr. Messages quote the user's own strings (a --set value, a scene's
// kind, a file name), which may hold newlines or run to any length: control
// characters are shown escaped (\n, \x1b) and the line is cut at
// kMaxErrorLine characters, saying how much was left out.
#pragma once

#include <cstdio>
#include <string>

namespace st {

inline constexpr size_t kMaxErrorLine = 600;

inline std::string error_line(const std::string& message) {
    std::string out;
    size_t i = 0;
    for (; i < message.size() && out.size() < kMaxErrorLine; ++i) {
        const unsigned char c = static_cast<unsigned char>(message[i]);
        if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (c < 0x20 || c == 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        } else {
            out += char(c);
        }
    }
    if (i < message.size()) out += "... (" + std::to_string(message.size() - i) + " more characters)";
    return out;
}

}  // namespace st
