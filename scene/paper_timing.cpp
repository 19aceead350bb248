// paper_timing.cpp: see paper_timing.h.
#include "scene/paper_timing.h"

#include "scene/input_error.h"

namespace st {

std::optional<PaperTiming> PaperTiming::read(JsonReader& scene) {
    auto r = scene.object_if("paper");
    if (!r) return std::nullopt;
    PaperTiming t;
    t.source = r->string("source");
    t.row = r->string("row");
    t.hardware = r->string("hardware");
    t.fps = r->number("fps", 0, 1e6);
    if (!(t.fps > 0)) throw InputError(r->field("fps") + " must be above 0");
    for (const std::string* s : {&t.source, &t.row, &t.hardware})
        if (s->empty()) throw InputError(r->path() + ": source, row and hardware must not be empty");
    r->finish();
    return t;
}

}  // namespace st
