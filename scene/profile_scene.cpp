// profile_scene.cpp: the "profile" kind, rendering with diffusion profiles
// (Donner and Jensen Sec. 3; docs/profile-rendering.md). The material's
// profiles are tabulated on the host (scene/profile_material.h); the frame
// is texture-space passes (the irradiance entering each face, each texel's
// world position and area, its normal) and the gather from the camera.
//
// The shapes and their texture layouts: scene/profile_shape.h. Curved
// shapes draw the gather with the depth test (a closed ellipsoid's far
// side, a sheet bent past a half turn).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/input_error.h"
#include "scene/profile_albedo.h"
#include "scene/profile_scene.h"
#include "scene/scene_kinds.h"
#include "scene/uniform_values.h"

namespace st {

namespace {

Texture target_texture(const std::string& sampler, const std::string& target) {
    Texture t;
    t.sampler = sampler;
    t.target = target;
    t.set_filter(TextureFilter::Linear);
    t.set_wrap(TextureWrap::ClampToEdge);
    return t;
}

// A pass drawing the mesh at its texture coordinates into `target`.
Pass texture_space_pass(const std::string& target, int size, const ProfileMesh& mesh, const std::string& fragment,
                        std::vector<Uniform> uniforms, std::vector<Texture> textures) {
    Pass pass;
    pass.target = target;
    pass.width = pass.height = size;
    pass.format = TargetFormat::RGBA32F;
    DrawCall d;
    d.vertex = "texture_space";
    d.fragment = fragment;
    d.vertices = mesh.vertices;
    d.indices = mesh.indices;
    d.uniforms = std::move(uniforms);
    d.textures = std::move(textures);
    pass.draws.push_back(std::move(d));
    return pass;
}

glm::vec3 unit3(JsonReader& r, const std::string& key) {
    const std::vector<double> v = r.numbers(key);
    const glm::dvec3 d(v[0], v[1], v[2]);
    if (!(glm::length(d) > 1e-12)) throw InputError("field '" + r.field(key) + "' must not be the zero vector");
    return glm::vec3(glm::normalize(d));
}

}  // namespace

// Every field's domain and default: scene/profile_space.cpp.
ProfileSceneSpec read_profile_scene(JsonReader& scene) {
    ProfileSceneSpec spec;
    JsonReader material_r = scene.object("material");
    spec.material = read_profile_material(material_r);

    JsonReader geometry_r = scene.object("geometry");
    spec.shape = read_profile_shape(geometry_r);
    spec.thickness_map = read_thickness_map(geometry_r, spec.shape);
    spec.texture_size = geometry_r.integer("texture_size");
    geometry_r.finish();

    JsonReader view_r = scene.object("view");
    spec.view_angle = view_r.number("angle_deg") * std::numbers::pi / 180.0;
    spec.view_azimuth = view_r.number("azimuth_deg") * std::numbers::pi / 180.0;
    const double extent = spec.shape.kind == "ellipsoid"
                              ? 2.0 * std::max({spec.shape.radii.x, spec.shape.radii.y, spec.shape.radii.z})
                              : spec.shape.size_mm;
    // By default twice the shape's extent.
    spec.view_distance = view_r.has("distance_mm") ? view_r.number("distance_mm") : 2.0 * extent;
    spec.fov = view_r.number("fov_deg") * std::numbers::pi / 180.0;
    view_r.finish();

    // A directional light; its pattern (a spot, a shadow edge) as
    // irradiance.frag describes it.
    JsonReader light_r = scene.object("light");
    spec.light_direction = unit3(light_r, "direction");
    const std::vector<double> e0 = light_r.numbers("irradiance");
    if (e0.size() == 2) throw InputError("field 'light.irradiance' needs one value or three (R, G, B)");
    spec.irradiance = e0.size() == 3 ? glm::vec3(float(e0[0]), float(e0[1]), float(e0[2])) : glm::vec3(float(e0[0]));
    if (auto sp = light_r.object_if("spot")) {
        const std::vector<double> c = sp->numbers("centre_mm");
        spec.spot = glm::vec4(float(c[0]), float(c[1]), float(sp->number("radius_mm")), 0.0f);
        sp->finish();
    }
    if (auto e = light_r.object_if("edge")) {
        const std::vector<double> n = e->numbers("normal");
        const double len = std::hypot(n[0], n[1]);
        if (!(len > 1e-12)) throw InputError("field 'light.edge.normal' must not be the zero vector");
        spec.edge = glm::vec4(float(n[0] / len), float(n[1] / len), float(e->number("offset_mm")), 1.0f);
        e->finish();
    }
    light_r.finish();

    if (auto a = scene.object_if("albedo")) {
        spec.albedo = read_albedo_map(*a);
        // Its convolution runs over the shape's exact surface.
        if (spec.albedo.textured() && !spec.shape.exact())
            throw InputError("field '" + scene.field("albedo") + "': texturing needs a generated shape (slab, sheet, "
                             "ellipsoid); a mesh has no exact surface here");
    }
    JsonReader g = scene.object_or_defaults("gather");
    spec.gather.pattern = g.choice("pattern");
    spec.gather.samples = g.integer("samples");
    spec.gather.table_size = g.integer("table_size");
    spec.gather.tail_fraction = g.number("tail_fraction");
    g.finish();
    return spec;
}

glm::dvec3 profile_eye(const ProfileSceneSpec& spec) {
    // The camera: `distance_mm` from the origin (the slab's centre), `angle_deg`
    // from the z axis (the slab's normal), `azimuth_deg` around it.
    const double theta = spec.view_angle, phi = spec.view_azimuth;
    return spec.view_distance *
           glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

glm::mat4 profile_view_proj(const ProfileSceneSpec& spec, SceneSize size) {
    const ProfileMesh mesh = profile_mesh(spec.shape);
    const double theta = spec.view_angle, distance = spec.view_distance;
    const glm::dvec3 eye = profile_eye(spec);
    const glm::dvec3 up = theta < 1e-6 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    const glm::dvec3 forward = -glm::normalize(eye);
    double nearest = 1e30, farthest = 0;
    for (const glm::dvec3& c : mesh.bounds) {
        const double z = glm::dot(c - eye, forward);
        nearest = std::min(nearest, z), farthest = std::max(farthest, z);
    }
    if (!(nearest > 1e-6 * distance))
        throw InputError("field 'view.distance_mm': the camera is inside or beside the " + spec.shape.kind +
                         "; move it further away");
    return glm::perspective(float(spec.fov), float(size.width) / float(size.height), float(0.5 * nearest),
                            float(2.0 * farthest)) *
           glm::lookAt(glm::vec3(eye), glm::vec3(0.0f), glm::vec3(up));
}

Frame build_profile_scene(JsonReader& scene, SceneSize size) {
    const ProfileSceneSpec spec = read_profile_scene(scene);
    const ProfileMaterial& material = spec.material;
    const GatherSettings& gather = spec.gather;
    const int target_size = spec.texture_size;
    const ProfileMesh mesh = profile_mesh(spec.shape);
    const glm::vec3 light_direction = spec.light_direction, irradiance = spec.irradiance;
    const glm::vec4 spot = spec.spot, edge = spec.edge;
    const std::shared_ptr<const BuiltProfiles> profiles = build_profiles(material, gather);
    Frame frame;
    auto target = [&](const std::string& name) {
        frame.targets.push_back(RenderTarget{name, target_size, target_size, TargetFormat::RGBA32F, 1});
    };
    const bool thin = material.thin();
    auto irradiance_pass = [&](const std::string& name, float back_offset) {
        target(name);
        frame.passes.push_back(texture_space_pass(
            name, target_size, mesh, "irradiance",
            {uniform("light_direction", light_direction), uniform("light_irradiance", irradiance),
             uniform("eta", float(material.eta())), int_uniform("rough", material.roughness() > 0 ? 1 : 0),
             uniform("back_offset", back_offset), uniform("spot", spot), uniform("edge", edge)},
            {profiles->rho_dt}));
    };
    irradiance_pass("irradiance", 0.0f);
    if (thin) irradiance_pass("irradiance_back", float(material.thickness()));
    for (int channel = 0; channel < 2; ++channel) {
        const std::string name = channel == 0 ? "position_area" : "surface_normal";
        target(name);
        frame.passes.push_back(texture_space_pass(
            name, target_size, mesh, "surface",
            {int_uniform("channel", channel), uniform("displacement", float(spec.thickness_map.height_mm))},
            {thickness_texture(spec.thickness_map, spec.shape, target_size)}));
    }

    const glm::mat4 view_proj = profile_view_proj(spec, size);

    DrawCall d;
    d.vertex = "profile";
    d.fragment = thin ? "gather_thin" : "gather";
    d.vertices = mesh.vertices;
    d.indices = mesh.indices;
    d.state.depth_test = spec.shape.curved();
    d.textures = {target_texture("irradiance", "irradiance")};
    if (thin) d.textures.push_back(target_texture("irradiance_back", "irradiance_back"));
    d.textures.push_back(target_texture("position_area", "position_area"));
    d.textures.push_back(target_texture("surface_normal", "surface_normal"));
    d.textures.push_back(profiles->profile_R);
    d.textures.push_back(profiles->profile_T);
    d.textures.push_back(profiles->pattern);
    d.textures.push_back(scene_albedo_texture(spec.albedo, spec.shape, profiles, thin, target_size));
    d.uniforms = {uniform("view_proj", view_proj),
                  int_uniform("samples", gather.samples),
                  uniform("r_max", float(profiles->r_max)),
                  uniform("profile_size", float(gather.table_size)),
                  uniform("texel_uv", 1.0f / float(target_size))};
    // The rough boundary's reflection (Eq. 23): m the RMS slope.
    const double m = material.roughness();
    for (Uniform u : {int_uniform("rough", m > 0 ? 1 : 0), uniform("eta", float(material.eta())),
                      uniform("inv_m2", m > 0 ? float(1.0 / (m * m)) : 0.0f),
                      uniform("beckmann_norm", m > 0 ? float(1.0 / (std::numbers::pi * m * m)) : 0.0f),
                      uniform("eye", glm::vec3(profile_eye(spec))), uniform("light_direction", light_direction),
                      uniform("light_irradiance", irradiance), uniform("spot", spot), uniform("edge", edge)})
        d.uniforms.push_back(u);
    Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    pass.clear_colour = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    pass.draws.push_back(std::move(d));
    frame.passes.push_back(std::move(pass));
    return frame;
}

}  // namespace st
