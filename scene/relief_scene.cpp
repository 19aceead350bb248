// relief_scene.cpp: the "relief" kind, Timonen's translucent relief mapping
// (Table 1's rows as `technique`). The surface is the plane z = 0 seen from
// a camera on a sphere around the origin; the quad is exactly the part of
// the plane a slightly widened frustum sees, so it covers the whole screen
// (as the paper measures) and no vertex needs clipping. Its maps are
// generated here (scene/relief_maps.h).
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/input_error.h"
#include "image/image_io.h"
#include "scene/relief_maps.h"
#include "scene/scene_kinds.h"
#include "scene/uniform_values.h"

namespace st {

namespace {

struct View {
    glm::dvec3 eye, forward, right, up;
    double tan_half_x, tan_half_y;
};

// The four points where the frustum's corner rays, widened by 5 %, meet the
// plane z = 0, counter-clockwise as seen from above. With a horizon
// distance, a corner ray that does not meet the plane within it (a grazing
// view) is replaced by the point of the plane that far from the camera in
// its direction: the surface then ends there and the clear colour shows
// above it.
std::array<glm::dvec3, 4> visible_quad(const View& v, double horizon) {
    std::array<glm::dvec3, 4> corners;
    const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    for (int k = 0; k < 4; ++k) {
        const glm::dvec3 d = v.forward + (sx[k] * 1.05 * v.tan_half_x) * v.right + (sy[k] * 1.05 * v.tan_half_y) * v.up;
        const bool meets = d.z < -1e-3 * glm::length(d);
        const glm::dvec3 hit = meets ? v.eye + d * (-v.eye.z / d.z) : glm::dvec3(0.0);
        const double reach = glm::length(glm::dvec2(hit - v.eye));
        if (horizon > 0.0 && (!meets || reach > horizon)) {
            const glm::dvec2 across = glm::normalize(glm::dvec2(d.x, d.y));
            corners[size_t(k)] = glm::dvec3(glm::dvec2(v.eye) + across * horizon, 0.0);
            continue;
        }
        if (!meets)
            throw InputError("field 'view.angle_deg': the view reaches the horizon, so the surface cannot cover the "
                             "screen (at most 90 - fov/2 - a margin, or give view.horizon_distance)");
        corners[size_t(k)] = hit;
    }
    return corners;
}

// A height map read from an image: its red channel, one height per texel
// (row 0 of the image is the top, texture row 0 the bottom, as GL uploads
// a picture). Refuses what the relief maps cannot hold, naming the field.
HeightField height_map_file(const std::string& path) {
    Image image;
    try {
        image = read_image(path);
    } catch (const std::exception& e) {
        throw InputError("field 'surface.height_map': " + std::string(e.what()));
    }
    if (image.width != image.height || image.width < 4 || image.width > 4096)
        throw InputError("field 'surface.height_map': " + path + " is " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + "; a height map is square, 4 to 4096 texels a side");
    HeightField f{image.width, std::vector<double>(size_t(image.width) * size_t(image.width))};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float h = image.pixel(x, image.height - 1 - y)[0];
            if (!(h >= 0.0f && h <= 1.0f))
                throw InputError("field 'surface.height_map': " + path + " has a height outside [0, 1] at texel (" +
                                 std::to_string(x) + ", " + std::to_string(image.height - 1 - y) + ")");
            f.h[size_t(y) * size_t(f.size) + size_t(x)] = h;
        }
    return f;
}

// A full-screen pass of the blooming chain: the triangles' "textured"
// vertex program on a quad with uv 0..1, into `target` (empty: the frame).
Pass screen_pass(const std::string& target, int width, int height, const std::string& fragment,
                 std::vector<std::pair<std::string, std::string>> reads, std::vector<Uniform> uniforms) {
    Pass pass;
    pass.target = target;
    pass.format = target.empty() ? TargetFormat::RGBA32F : TargetFormat::RGBA16F;  // the frame is RGBA32F
    pass.width = width;
    pass.height = height;
    pass.clear_colour = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    DrawCall d;
    d.vertex = "textured";
    d.fragment = fragment;
    d.vertices.attribute_count = 3;  // position (clip), colour, uv
    const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& c : corner) {
        d.vertices.data.push_back(glm::vec4(c[0], c[1], 0.0f, 1.0f));
        d.vertices.data.push_back(glm::vec4(1.0f));
        d.vertices.data.push_back(glm::vec4(0.5f * (c[0] + 1.0f), 0.5f * (c[1] + 1.0f), 0.0f, 1.0f));
    }
    d.indices = {0, 1, 2, 0, 2, 3};
    for (const auto& [sampler, from] : reads) {
        Texture t;
        t.sampler = sampler;
        t.target = from;
        t.set_filter(TextureFilter::Linear);
        t.set_wrap(TextureWrap::ClampToEdge);
        d.textures.push_back(std::move(t));
    }
    d.uniforms = std::move(uniforms);
    pass.draws.push_back(std::move(d));
    return pass;
}

// The blooming chain after the scene's pass (glsl/relief/bloom_*.frag):
// the HDR part separated at full size, down-sampled twice by bilinear
// halving (each output pixel the 2x2 average its footprint's centre reads),
// blurred along x then y at a quarter of the size, and added back to the
// frame's displayable part. RGBA16F targets, as an HDR chain on a GPU keeps.
Frame with_bloom(Pass scene_pass, SceneSize size, float threshold, float strength) {
    const int w = size.width, h = size.height, hw = std::max(1, w / 2), hh = std::max(1, h / 2);
    const int qw = std::max(1, w / 4), qh = std::max(1, h / 4);
    Frame f;
    auto target = [&](const std::string& name, int tw, int th) {
        f.targets.push_back(RenderTarget{name, tw, th, TargetFormat::RGBA16F, 1});
    };
    target("hdr", w, h);
    target("bright", w, h);
    target("half", hw, hh);
    target("quarter", qw, qh);
    target("blur_x", qw, qh);
    target("blur_xy", qw, qh);
    scene_pass.target = "hdr";
    scene_pass.format = TargetFormat::RGBA16F;
    f.passes.push_back(std::move(scene_pass));
    f.passes.push_back(screen_pass("bright", w, h, "bloom_bright", {{"hdr", "hdr"}}, {uniform("threshold", threshold)}));
    f.passes.push_back(screen_pass("half", hw, hh, "textured", {{"tex", "bright"}}, {}));
    f.passes.push_back(screen_pass("quarter", qw, qh, "textured", {{"tex", "half"}}, {}));
    f.passes.push_back(screen_pass("blur_x", qw, qh, "bloom_blur", {{"src", "quarter"}},
                                   {uniform("texel_step", glm::vec2(1.0f / float(qw), 0.0f))}));
    f.passes.push_back(screen_pass("blur_xy", qw, qh, "bloom_blur", {{"src", "blur_x"}},
                                   {uniform("texel_step", glm::vec2(0.0f, 1.0f / float(qh)))}));
    f.passes.push_back(screen_pass("", w, h, "bloom_composite", {{"hdr", "hdr"}, {"bloom", "blur_xy"}},
                                   {uniform("strength", strength)}));
    return f;
}

}  // namespace

Frame build_relief_scene(JsonReader& scene, SceneSize size) {
    const std::string technique = scene.choice("technique");

    // The camera: `distance` from the origin, `angle_deg` from the surface
    // normal (0 looks straight down), `azimuth_deg` around it.
    JsonReader view_r = scene.object("view");
    const double theta = view_r.number("angle_deg") * std::numbers::pi / 180.0;
    const double phi = view_r.number("azimuth_deg") * std::numbers::pi / 180.0;
    const double distance = view_r.number("distance");
    const double fov = view_r.number("fov_deg") * std::numbers::pi / 180.0;
    // 0: the surface must cover the screen (Table 1's measurements).
    const double horizon = view_r.number("horizon_distance");
    view_r.finish();

    JsonReader light_r = scene.object("light");
    const std::vector<double> lp = light_r.numbers("position");
    light_r.finish();

    JsonReader surface_r = scene.object("surface");
    StoneParams stones;
    // "flat": the stones' colour on a height field of one value, the
    // degenerate case the failure tests use (1: the top, 0: the floor).
    // "walls": walls of height 1 and one texel wide every `wall_spacing`
    // texels in both directions on a floor at 0, the features thinner than
    // a linear step that the failure tests need.
    // "file": the heights from an image (its red channel, in [0, 1]; a path
    // relative to the working directory), square, with the stones' colours;
    // its size is the map size.
    const std::string heights = surface_r.choice("heights");
    HeightField from_file;
    if (heights == "file") {
        from_file = height_map_file(surface_r.text("height_map"));
        stones.size = from_file.size;
        // A scene may keep its map_size (the built-in ones do) if it agrees.
        if (surface_r.has("map_size") && surface_r.integer("map_size") != stones.size)
            throw InputError("field 'surface.map_size' is not the height map's size (" + std::to_string(stones.size) +
                             ")");
    } else {
        stones.size = surface_r.integer("map_size");
    }
    stones.cells = surface_r.integer("stones");
    stones.seed = uint32_t(surface_r.integer("seed"));
    const double depth = surface_r.number("depth");  // in texture coordinates
    const double uv_per_unit = surface_r.number("uv_per_unit");
    const bool flat = heights == "flat";
    const double flat_height = flat ? surface_r.number("flat_height") : 0.0;
    const int wall_spacing = heights == "walls" ? surface_r.integer_in("wall_spacing", 2, stones.size) : 0;
    surface_r.finish();

    // The search (relief and later rows); its domains (scene/relief_space.cpp)
    // refuse step counts that would run for seconds.
    JsonReader search = scene.object_or_defaults("search");
    const int linear_steps = search.integer("linear_steps");
    const int binary_steps = search.integer("binary_steps");
    const bool secant = search.boolean("secant");
    // Row 2 only: the count scaled by the view angle (relief_mapping.frag).
    const int min_linear_steps = technique == "relief" ? search.integer_in("min_linear_steps", 0, linear_steps) : 0;
    search.finish();

    // The translucent medium and the environment (two-layer and later rows).
    // Rows 3-5 are one shader family, each row switching on what it adds.
    const bool two_layer = technique == "two-layer" || technique == "occlusion" || technique == "absorption";
    const bool occlusion = technique == "occlusion" || technique == "absorption";
    const bool absorption = technique == "absorption";
    DropParams drops;
    drops.size = stones.size;
    double liquid_depth = 0.1, ior = 1.33, shadow_bias = 0.02;
    int max_crossings = 4;
    glm::vec3 half_distance(1.0f);
    if (two_layer) {
        JsonReader liquid_r = scene.object("liquid");
        liquid_depth = liquid_r.number("depth");
        ior = liquid_r.number("ior");
        drops.drops = liquid_r.integer("drops");
        drops.seed = uint32_t(liquid_r.integer("seed"));
        drops.level = liquid_r.number("level");
        drops.min_radius = liquid_r.number("min_radius");
        drops.max_radius = liquid_r.number_in("max_radius", drops.min_radius, 0.5);
        drops.min_peak = liquid_r.number_in("min_peak", drops.level, 1.0);
        drops.max_peak = liquid_r.number_in("max_peak", drops.min_peak, 1.0);
        if (absorption) {
            const std::vector<double> d0 = liquid_r.numbers("half_distance");
            half_distance = glm::vec3(float(d0[0]), float(d0[1]), float(d0[2]));
        }
        if (occlusion) {
            max_crossings = liquid_r.integer("max_crossings");
            shadow_bias = liquid_r.number("shadow_bias");
        }
        liquid_r.finish();
    }
    // Planar local reflections (rows 3-5): the refracted and reflected view
    // rays against a flat plane at plane_height instead of searched.
    bool planar = false;
    double plane_height = 0.5;
    if (two_layer) {
        JsonReader refl = scene.object_or_defaults("reflections");
        planar = refl.boolean("planar");
        plane_height = refl.number("plane_height");
        refl.finish();
    }
    int sky_size = 64;
    std::vector<double> sun{0.4, 0.3, 0.6};
    double sun_radiance = 30.0, sun_radius = 2.0;
    if (two_layer) {
        JsonReader env_r = scene.object("environment");
        sky_size = env_r.integer("size");
        sun = env_r.numbers("sun_direction");
        sun_radiance = env_r.number("sun_radiance");
        sun_radius = env_r.number("sun_radius_deg");
        env_r.finish();
        if (!(sun[0] * sun[0] + sun[1] * sun[1] + sun[2] * sun[2] > 0.0))
            throw InputError("field 'environment.sun_direction' must not be the zero vector");
    }

    // Light blooming (Sec. 3.2), rows 3-5: the frame rendered into an HDR
    // target, then passes that separate, down-sample, blur and add back.
    bool bloom = false;
    double bloom_threshold = 1.0, bloom_strength = 1.0;
    if (two_layer) {
        if (auto bloom_r = scene.object_if("bloom")) {
            bloom = bloom_r->boolean("enabled");
            bloom_threshold = bloom_r->number("threshold");
            bloom_strength = bloom_r->number("strength");
            bloom_r->finish();
        }
        if (bloom && (size.width < 8 || size.height < 8))
            throw InputError("field 'bloom': blooming needs a frame of at least 8x8 (it blurs a quarter-size copy)");
    }

    JsonReader shading_r = scene.object("shading");
    const float ambient = float(shading_r.number("ambient"));
    const float specular = float(shading_r.number("specular"));
    // The medium's highlight (rows 3-5 and later): off unless asked for.
    const float liquid_specular = two_layer ? float(shading_r.number("liquid_specular")) : 0.0f;
    const bool intensify = two_layer && shading_r.boolean("intensify");
    shading_r.finish();

    View v;
    v.eye = distance * glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    v.forward = -glm::normalize(v.eye);
    // Screen-up points away from the camera across the plane (straight
    // down, it is +y).
    const glm::dvec3 world_up = theta < 1e-6 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    v.right = glm::normalize(glm::cross(v.forward, world_up));
    v.up = glm::cross(v.right, v.forward);
    v.tan_half_y = std::tan(0.5 * fov);
    v.tan_half_x = v.tan_half_y * double(size.width) / double(size.height);
    const std::array<glm::dvec3, 4> quad = visible_quad(v, horizon);

    // Near and far bracket the quad's depths along the view direction.
    double nearest = 1e30, farthest = 0;
    for (const glm::dvec3& c : quad) {
        const double z = glm::dot(c - v.eye, v.forward);
        nearest = std::min(nearest, z), farthest = std::max(farthest, z);
    }
    const glm::mat4 view_proj =
        glm::perspective(float(fov), float(size.width) / float(size.height), float(0.5 * nearest),
                         float(2.0 * farthest)) *
        glm::lookAt(glm::vec3(v.eye), glm::vec3(0.0f), glm::vec3(v.up));

    DrawCall draw;
    draw.vertex = "relief";
    draw.fragment = technique == "normal-mapping" ? "normal_mapping" : two_layer ? "two_layer" : "relief_mapping";
    draw.vertices.attribute_count = 2;
    for (const glm::dvec3& c : quad) {
        draw.vertices.data.push_back(glm::vec4(float(c.x), float(c.y), 0.0f, 1.0f));
        draw.vertices.data.push_back(glm::vec4(float(c.x * uv_per_unit), float(c.y * uv_per_unit), 0.0f, 1.0f));
    }
    draw.indices = {0, 1, 2, 0, 2, 3};
    HeightField solid;
    if (heights == "file") {
        solid = std::move(from_file);
    } else if (heights == "stones") {
        solid = stone_heights(stones);
    } else {
        solid = HeightField{stones.size, std::vector<double>(size_t(stones.size) * size_t(stones.size), flat_height)};
        if (wall_spacing > 0)
            for (int y = 0; y < stones.size; ++y)
                for (int x = 0; x < stones.size; ++x)
                    if (x % wall_spacing == 0 || y % wall_spacing == 0) solid.h[size_t(y) * size_t(stones.size) + size_t(x)] = 1.0;
    }
    draw.textures.push_back(relief_texture(solid, depth, "relief_map"));
    draw.textures.push_back(stone_colour_texture(stones, "colour_map"));
    if (two_layer) {
        draw.textures.push_back(relief_texture(drop_heights(drops), liquid_depth, "liquid_map"));
        draw.textures.push_back(
            sky_cube_texture(sky_size, glm::dvec3(sun[0], sun[1], sun[2]), sun_radiance, sun_radius, "environment"));
    }
    draw.uniforms = {uniform("view_proj", view_proj),
                     uniform("eye", glm::vec3(v.eye)),
                     uniform("light", glm::vec3(float(lp[0]), float(lp[1]), float(lp[2]))),
                     uniform("ambient", ambient),
                     uniform("specular", specular)};
    if (technique != "normal-mapping") {
        draw.uniforms.push_back(uniform("depth", float(depth)));
        if (two_layer) {
            draw.uniforms.push_back(uniform("liquid_depth", float(liquid_depth)));
            draw.uniforms.push_back(uniform("world_per_uv", float(1.0 / uv_per_unit)));
            draw.uniforms.push_back(uniform("ior", float(ior)));
            draw.uniforms.push_back(int_uniform("occlusion", occlusion ? 1 : 0));
            draw.uniforms.push_back(int_uniform("absorption", absorption ? 1 : 0));
            draw.uniforms.push_back(int_uniform("max_crossings", max_crossings));
            draw.uniforms.push_back(uniform("shadow_bias", float(shadow_bias)));
            draw.uniforms.push_back(uniform("half_distance", half_distance));
            draw.uniforms.push_back(uniform("liquid_specular", liquid_specular));
            draw.uniforms.push_back(int_uniform("intensify", intensify ? 1 : 0));
            draw.uniforms.push_back(int_uniform("planar", planar ? 1 : 0));
            draw.uniforms.push_back(uniform("plane_height", float(plane_height)));
        } else {
            draw.uniforms.push_back(uniform("world_depth", float(depth / uv_per_unit)));
            draw.uniforms.push_back(int_uniform("min_linear_steps", min_linear_steps));
        }
        draw.uniforms.push_back(int_uniform("linear_steps", linear_steps));
        draw.uniforms.push_back(int_uniform("binary_steps", binary_steps));
        draw.uniforms.push_back(int_uniform("secant", secant ? 1 : 0));
    }

    Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    pass.clear_colour = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    pass.draws.push_back(std::move(draw));
    Frame frame;
    if (bloom) return with_bloom(std::move(pass), size, float(bloom_threshold), float(bloom_strength));
    frame.passes.push_back(std::move(pass));
    return frame;
}

}  // namespace st
