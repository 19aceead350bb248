// profile_scene.h: what a "profile" scene says (profile_scene.cpp builds
// its frame from it), for the tools that measure it against the exact
// rendering (app/profile_exact.h).
#pragma once

#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/json_reader.h"
#include "scene/profile_albedo.h"
#include "scene/profile_material.h"
#include "scene/profile_shape.h"
#include "scene/profile_thickness.h"
#include "scene/scene_kinds.h"

namespace st {

struct ProfileSceneSpec {
    ProfileMaterial material;
    GatherSettings gather;
    ProfileShape shape;
    ThicknessMap thickness_map;
    AlbedoMap albedo;  // Sec. 3.1
    int texture_size = 256;
    double view_angle = 0, view_azimuth = 0, view_distance = 80, fov = 0.8;  // radians, mm
    glm::vec3 light_direction{0, 0, 1};  // unit, towards the light
    glm::vec3 irradiance{1.0f};
    glm::vec4 spot{0.0f};  // xy centre, z radius (mm); z = 0: none
    glm::vec4 edge{0.0f};  // xy unit normal, z offset; w = 0: none
};

// Reads the kind's fields (not finishing the scene object); InputError
// names a bad one.
ProfileSceneSpec read_profile_scene(JsonReader& scene);
glm::mat4 profile_view_proj(const ProfileSceneSpec& spec, SceneSize size);
glm::dvec3 profile_eye(const ProfileSceneSpec& spec);  // world, mm

}  // namespace st
