// wrap_technique.cpp: what the technique adds to the tool: each twin under
// the stem of the GLSL file it mirrors, and its scene kind.
#include "sdk/technique.h"
#include "wrap.h"

SHADERTWIN_TECHNIQUE(wrap, technique) {
    technique.vertex_twin<WrapVertex>("wrap");
    technique.fragment_twin<WrapFragment>("wrap");
    technique.scene_kind("wrap", build_wrap_scene);
}
