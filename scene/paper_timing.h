// paper_timing.h: the frame rate a paper published for what a scene renders,
// one row of the paper's fps table, so that a report can set our two
// backends' rates beside it (docs/scenes.md, field "paper").
#pragma once

#include <optional>
#include <string>

#include "scene/json_reader.h"

namespace st {

struct PaperTiming {
    std::string source;    // where the number is: "Timonen 2006, Table 1"
    std::string row;       // the paper's name for the row: "Relief mapping"
    std::string hardware;  // what the paper measured on: "GeForce 7600GS"
    double fps = 0;        // frames per second, as published

    // The scene's optional "paper" object; std::nullopt when absent. Throws
    // InputError on a missing or mistyped field, or an fps not in (0, 1e6].
    static std::optional<PaperTiming> read(JsonReader& scene);
};

}  // namespace st
