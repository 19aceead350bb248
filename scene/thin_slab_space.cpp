// thin_slab_space.cpp: the fields of a "thin-slab" scene (Frisvad et al.'s
// case study, a waving flag before a painting; scene/thin_slab_scene.cpp
// builds it), with their domains. Lengths in world units.
#include "scene/scene_spaces.h"

namespace st {

const ParamSpace& thin_slab_space() {
    static const ParamSpace space = [] {
        ParamSpace s("thin-slab");
        s.include(common_space());
        s.choice("variant", {"fragment", "vertex", "host", "baseline"}, "fragment",
                 "where Eq. 4-8 are evaluated: per fragment, per vertex, on the host per vertex; or the Lambert baseline");

        s.object("material", true, "the slab's optics");
        s.number("material.tau1", 0, 1e6, "required", "optical thickness").draws(0, 10).edge({0, 1e-6});
        s.numbers("material.albedo", 3, 3, 0, 1, "required",
                  "single-scattering albedo per channel, times the flag's texel");

        s.object("light", true, "a point light circling the flag's vertical axis");
        s.number("light.power", 0, 1e12, "required", "flux Phi of the point light (Eq. 6)").draws(1, 1e4).log().edge({0});
        s.number("light.orbit_radius", 0, 1e6, 3.0, "the circle's radius about the y axis").draws(0, 10).edge({0});
        s.number("light.orbit_height", -1e6, 1e6, 0.5, "the circle's height").draws(-3, 3);
        s.number("light.angle_deg", -1e6, 1e6, 0.0, "position on the circle, degrees; 0 is +z, the camera's side")
            .draws(-360, 360).edge({0, 90, 180, -90});
        s.numbers("light.position", 3, 3, -1e6, 1e6, nullptr, "world position; wins over the orbit when given")
            .draws(-5, 5);

        s.object("camera", true, "a perspective camera; the image's width and height set its aspect ratio");
        s.numbers("camera.position", 3, 3, -1e6, 1e6, "required", "the eye (also the shader's `eye`)").draws(-10, 10);
        s.numbers("camera.target", 3, 3, -1e6, 1e6, "required", "the look-at point").draws(-2, 2);
        s.numbers("camera.up", 3, 3, -1e6, 1e6, nlohmann::json::array({0.0, 1.0, 0.0}),
                  "up; with position and target it must define a view (not parallel to the line of sight)")
            .draws(-1, 1);
        s.number("camera.fov_deg", 1, 170, 40.0, "vertical field of view, degrees");
        s.number("camera.near", 1e-6, 1e6, 0.1, "near plane distance").draws(1e-3, 10).log();
        s.number("camera.far", 1e-6, 1e9, 100.0, "far plane distance; must exceed `camera.near`")
            .at_least("camera.near").draws(1, 1e3).log();

        s.object("flag", true, "the flag, centred on the origin in the x-y plane, its pole at x = -width/2");
        s.number("flag.width", 1e-6, 1e6, 2.2, "flag width").draws(0.1, 10).log();
        s.number("flag.height", 1e-6, 1e6, 1.6, "flag height").draws(0.1, 10).log();
        s.integer("flag.columns", 1, 2048, 44, "mesh resolution across (quads)").explore_at_most(256).edge({1, 2});
        s.integer("flag.rows", 1, 2048, 32, "mesh resolution up (quads)").explore_at_most(256).edge({1, 2});
        s.number("flag.wave_amplitude", 0, 1e6, 0.12, "A in z = A u sin(2 pi (f u - t) + 1.3 v)").draws(0, 1).edge({0});
        s.number("flag.wave_frequency", 0, 1e3, 1.2, "f, waves across the flag").draws(0, 5).edge({0});
        s.number("flag.time", -1e6, 1e6, 0.0, "t, the animation time").draws(-2, 2);
        s.integer("flag.texture_width", 22, 4096, 220, "flag texture width (the cross needs 22 texels)")
            .explore_at_most(1024);
        s.integer("flag.texture_height", 16, 4096, 160, "flag texture height (the cross needs 16 texels)")
            .explore_at_most(1024);

        s.object("background", false, "the painting behind the flag, drawn over the whole image");
        s.integer("background.texture_width", 1, 4096, 512, "painting width; at the image size sampled texel for texel")
            .explore_at_most(1024).edge({1, 2});
        s.integer("background.texture_height", 1, 4096, 512, "painting height").explore_at_most(1024).edge({1, 2});
        return s;
    }();
    return space;
}

}  // namespace st
