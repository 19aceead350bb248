// quality_resolver.h: `quality: auto` for every technique that has a choice
// to make ("model no more than a scene needs", issues 11 and 28). A scene
// with "quality": "auto" (and optionally "quality_budget", 8-bit steps) is
// resolved before it is built, by its kind:
// - profile: the diffusion model and gather samples (profile_quality.h);
// - relief: the search, reflections and light crossings (relief_quality.h);
// - thin-slab: where Eq. 4-8 are evaluated (thin_slab_quality.h).
// Each choice is measured once per scene document and budget, kept in the
// profile cache (scene/profile_cache.h) with its record, and the record
// travels with the scene (Scene::quality) to compare, render and the
// report. When no candidate meets the budget, the most accurate setting is
// used and one line on stderr says so.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "gl/gl_platform.h"

namespace st {

// Makes load_scene resolve `quality: auto`, rendering with `threads` CPU
// threads.
void install_quality_resolver(int threads, GlPlatform gl_platform);

// A record (Scene::quality) in one line, as compare and the report show it:
// "quality auto: 16 / 12 / secant (0.96 % of the object over 1 steps, p99
// 1, max 226); CPU 20.4 ms, the most accurate 179 ms when measured".
std::string quality_summary(const nlohmann::json& record);

}  // namespace st
