// thin_slab_scene.cpp: the "thin-slab" kind, the paper's case study
// (Frisvad et al., Sec. 4): a waving flag of the Faroe Islands in front of a
// background painting, lit by a point light circling the flag.
//
// Everything geometric is computed here on the host, once, so both backends
// receive identical numbers: the displaced flag mesh with its normals, the
// camera matrix, the light position, the procedural flag and painting. The
// `host` variant additionally evaluates Eq. 4-8 per vertex at the start of
// every frame (ThinSlabHostStage), as the paper's CPU variant does.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "scene/input_error.h"
#include "scene/scene_kinds.h"
#include "scene/thin_slab_textures.h"
#include "scene/uniform_values.h"

namespace st {

namespace {


// Vertex layout of the host variant: the radiance slot is rewritten per frame.
[[maybe_unused]] constexpr int kHostPosition = 0, kHostRadiance = 1, kHostUv = 2, kHostNormal = 3;

class ThinSlabHostStage final : public HostStage {
public:
    ThinSlabHostStage(glm::vec3 eye, glm::vec3 light, float power, float tau1, glm::vec3 albedo)
        : eye_(eye), light_(light), power_(power), tau1_(tau1), albedo_(albedo) {}

    // kLanes vertices at a time through the model's lane form (the same
    // template as the per-vertex one, so the same bits per vertex); a last
    // short batch repeats its final vertex in the spare lanes.
    void run(VertexArray& va) const override {
        const int n = va.vertex_count();
        for (int first = 0; first < n; first += kLanes) {
            Vec3 p, normal;
            for (int lane = 0; lane < kLanes; ++lane) {
                const glm::vec4* a = va.vertex(std::min(first + lane, n - 1));
                for (int c = 0; c < 3; ++c) {
                    (p.*kComponent[c]).set(lane, a[kHostPosition][c]);
                    (normal.*kComponent[c]).set(lane, a[kHostNormal][c]);
                }
            }
            const Vec4 radiance = thin_slab(p, glsl::normalize(normal), Vec3(eye_), Vec3(light_), Float(power_),
                                            Float(tau1_), Vec3(albedo_));
            for (int lane = 0; lane < kLanes && first + lane < n; ++lane)
                va.data[size_t(first + lane) * size_t(va.attribute_count) + kHostRadiance] =
                    glm::vec4(radiance.x[lane], radiance.y[lane], radiance.z[lane], radiance.w[lane]);
        }
    }

    static constexpr Float Vec3::*kComponent[3] = {&Vec3::x, &Vec3::y, &Vec3::z};

private:
    glm::vec3 eye_, light_;
    float power_, tau1_;
    glm::vec3 albedo_;
};

glm::vec3 vec3_of(const std::vector<double>& v) { return glm::vec3(float(v[0]), float(v[1]), float(v[2])); }

struct FlagShape {
    double width, height, amplitude, frequency, time;
    int columns, rows;
};

// The flag hangs from a pole at its left edge (u = 0) and waves along x:
// z(u, v) = A u sin(2 pi (f u - t) + 1.3 v), so the pole side stays still.
// Positions and analytic normals in double, stored as float.
void flag_mesh(const FlagShape& f, bool host_layout, DrawCall& draw) {
    draw.vertices.attribute_count = host_layout ? 4 : 3;
    for (int j = 0; j <= f.rows; ++j)
        for (int i = 0; i <= f.columns; ++i) {
            const double u = double(i) / f.columns, v = double(j) / f.rows;
            const double phase = 2.0 * std::numbers::pi * (f.frequency * u - f.time) + 1.3 * v;
            const double x = (u - 0.5) * f.width, y = (v - 0.5) * f.height;
            const double z = f.amplitude * u * std::sin(phase);
            const double dzdu = f.amplitude * (std::sin(phase) + u * std::cos(phase) * 2.0 * std::numbers::pi * f.frequency);
            const double dzdv = f.amplitude * u * std::cos(phase) * 1.3;
            const double nx = -dzdu / f.width, ny = -dzdv / f.height, nz = 1.0;
            const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
            const glm::vec4 position(float(x), float(y), float(z), 1.0f);
            const glm::vec4 normal(float(nx / len), float(ny / len), float(nz / len), 0.0f);
            const glm::vec4 uv(float(u), float(v), 0.0f, 1.0f);
            if (host_layout) {
                for (const glm::vec4& a : {position, glm::vec4(0.0f), uv, normal}) draw.vertices.data.push_back(a);
            } else {
                for (const glm::vec4& a : {position, normal, uv}) draw.vertices.data.push_back(a);
            }
        }
    const int stride = f.columns + 1;
    for (int j = 0; j < f.rows; ++j)
        for (int i = 0; i < f.columns; ++i) {
            const uint32_t a = uint32_t(j * stride + i), b = a + 1, c = a + uint32_t(stride) + 1, d = a + uint32_t(stride);
            for (uint32_t k : {a, b, c, a, c, d}) draw.indices.push_back(k);
        }
}

DrawCall background_draw(const Texture& painting) {
    DrawCall draw;
    draw.vertex = draw.fragment = "background";
    draw.vertices.attribute_count = 2;
    const glm::vec4 corners[4][2] = {{{-1, -1, 1, 1}, {0, 0, 0, 1}}, {{1, -1, 1, 1}, {1, 0, 0, 1}},
                                     {{1, 1, 1, 1}, {1, 1, 0, 1}}, {{-1, 1, 1, 1}, {0, 1, 0, 1}}};
    for (const auto& c : corners) {
        draw.vertices.data.push_back(c[0]);
        draw.vertices.data.push_back(c[1]);
    }
    draw.indices = {0, 1, 2, 0, 2, 3};
    draw.textures.push_back(painting);
    return draw;
}

}  // namespace

Frame build_thin_slab_scene(JsonReader& scene, SceneSize size) {
    // Every field's domain and default: scene/thin_slab_space.cpp.
    const std::string variant = scene.choice("variant");

    JsonReader material = scene.object("material");
    const float tau1 = float(material.number("tau1"));
    const glm::vec3 albedo = vec3_of(material.numbers("albedo"));
    material.finish();

    // The light circles the flag's vertical axis: angle 0 puts it on the
    // camera's side (+z). An explicit `position` wins over the orbit.
    JsonReader light_r = scene.object("light");
    const float power = float(light_r.number("power"));
    const double radius = light_r.number("orbit_radius");
    const double height = light_r.number("orbit_height");
    const double angle = light_r.number("angle_deg") * std::numbers::pi / 180.0;
    glm::vec3 light(float(radius * std::sin(angle)), float(height), float(radius * std::cos(angle)));
    if (light_r.has("position")) light = vec3_of(light_r.numbers("position"));
    light_r.finish();

    JsonReader camera = scene.object("camera");
    const glm::vec3 eye = vec3_of(camera.numbers("position"));
    const glm::vec3 target = vec3_of(camera.numbers("target"));
    const glm::vec3 up = vec3_of(camera.numbers("up"));
    const float fov = float(camera.number("fov_deg"));
    const float near = float(camera.number("near"));
    // Declared at least `near`; refused below unless it exceeds it.
    const float far = float(camera.number_in("far", -kHuge, kHuge));
    camera.finish();
    if (!(far > near)) throw InputError("field 'camera.far' must exceed 'camera.near'");
    if (glm::length(glm::cross(target - eye, up)) == 0.0f)
        throw InputError("fields 'camera.position', 'camera.target' and 'camera.up' do not define a view");
    const glm::mat4 view_proj = glm::perspective(glm::radians(fov), float(size.width) / float(size.height), near, far) *
                                glm::lookAt(eye, target, up);

    JsonReader flag_r = scene.object("flag");
    FlagShape shape;
    shape.width = flag_r.number("width");
    shape.height = flag_r.number("height");
    shape.columns = flag_r.integer("columns");
    shape.rows = flag_r.integer("rows");
    shape.amplitude = flag_r.number("wave_amplitude");
    shape.frequency = flag_r.number("wave_frequency");
    shape.time = flag_r.number("time");
    const int flag_tex_w = flag_r.integer("texture_width");
    const int flag_tex_h = flag_r.integer("texture_height");
    flag_r.finish();

    JsonReader bg = scene.object_or_defaults("background");
    const int painting_w = bg.integer("texture_width");
    const int painting_h = bg.integer("texture_height");
    bg.finish();

    Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    pass.clear_colour = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    pass.draws.push_back(background_draw(painting_texture(painting_w, painting_h)));

    DrawCall flag;
    flag.state.blend = BlendMode::OneSrcAlpha;  // Eq. 9
    flag.textures.push_back(faroe_flag_texture(flag_tex_w, flag_tex_h));
    // Each variant's programs are given what they declare (every run checks
    // that: app/interface/uniform_interface.h); the host variant's model
    // reads the rest on the host.
    flag.uniforms = {uniform("view_proj", view_proj)};
    const std::vector<Uniform> model = {uniform("eye", eye), uniform("light", light), uniform("power", power),
                                        uniform("albedo", albedo)};
    if (variant == "fragment" || variant == "vertex") {
        flag.vertex = variant == "fragment" ? "thin_slab" : "thin_slab_vertex";
        flag.fragment = variant == "fragment" ? "thin_slab" : "thin_slab_lit";
        flag.uniforms.insert(flag.uniforms.end(), model.begin(), model.end());
        flag.uniforms.push_back(uniform("tau1", tau1));
    } else if (variant == "host") {
        flag.vertex = "thin_slab_host";
        flag.fragment = "thin_slab_lit";
        flag.host_stage = std::make_shared<ThinSlabHostStage>(eye, light, power, tau1, albedo);
    } else {  // the constant-alpha baseline: no tau1
        flag.vertex = "thin_slab";
        flag.fragment = "thin_slab_baseline";
        flag.uniforms.insert(flag.uniforms.end(), model.begin(), model.end());
    }
    flag_mesh(shape, variant == "host", flag);
    pass.draws.push_back(std::move(flag));

    Frame frame;
    frame.passes.push_back(std::move(pass));
    return frame;
}

}  // namespace st
