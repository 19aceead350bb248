// scene_kinds.h: one builder per kind of scene. A builder reads its own
// fields from the scene object (the common ones, kind/description/width/
// height/criteria, are read by load_scene) and fills the frame.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "frame/frame.h"
#include "scene/json_reader.h"

namespace st {

struct SceneSize {
    int width, height;
};

using SceneBuilder = std::function<Frame(JsonReader& scene, SceneSize size)>;

// kind name -> builder
const std::map<std::string, SceneBuilder>& scene_builders();
// Adds a user technique's kind (sdk/technique.h); throws InputError when
// the kind exists.
void register_scene_kind(const std::string& kind, SceneBuilder builder);

Frame build_triangles_scene(JsonReader& scene, SceneSize size);
Frame build_conformance_scene(JsonReader& scene, SceneSize size);
Frame build_thin_slab_scene(JsonReader& scene, SceneSize size);
Frame build_thin_slab_sweep_scene(JsonReader& scene, SceneSize size);
Frame build_relief_scene(JsonReader& scene, SceneSize size);
Frame build_profile_scene(JsonReader& scene, SceneSize size);

}  // namespace st
