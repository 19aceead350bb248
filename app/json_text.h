// json_text.h: a JSON value as the commands print it. File names and scene
// names come from the user and need not be UTF-8 (a Linux file name is any
// bytes); nlohmann's dump() would throw on them after the images are
// written, so invalid bytes become U+FFFD instead.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace st {

inline std::string json_text(const nlohmann::json& j, int indent = -1) {
    return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace st
