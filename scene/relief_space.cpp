// relief_space.cpp: the fields of a "relief" scene (Timonen's translucent
// relief mapping; scene/relief_scene.cpp builds it), with their domains.
// Step counts stop where a frame would take seconds, not where the method
// stops working: the failure tests and the explorer need the far ends.
#include "scene/scene_spaces.h"

namespace st {

const ParamSpace& relief_space() {
    static const ParamSpace space = [] {
        const std::vector<std::string> two_layer = {"two-layer", "occlusion", "absorption"};
        const std::vector<std::string> occluding = {"occlusion", "absorption"};
        ParamSpace s("relief");
        s.include(common_space());
        s.choice("technique", {"normal-mapping", "relief", "two-layer", "occlusion", "absorption"}, "relief",
                 "Table 1's row: normal mapping, relief mapping, two layers, light occlusion, hued absorption");

        s.object("view", true, "the camera on a sphere around the origin");
        s.number("view.angle_deg", 0, 89, 45.0, "from the surface normal, degrees (0 looks straight down)")
            .edge({0, 1e-4, 60, 80});
        s.number("view.azimuth_deg", -360, 360, 0.0, "around the normal, degrees").edge({0, 45, 90, -90});
        s.number("view.distance", 1e-3, 1e3, 2.0, "from the origin").draws(0.3, 20).log();
        s.number("view.fov_deg", 1, 120, 45.0, "vertical field of view, degrees");
        s.number("view.horizon_distance", 0, 1e4, 0.0,
                 "0: the surface must cover the screen; else where it ends, so a grazing view shows the horizon")
            .draws(0, 50);

        s.object("light", true, "a point light");
        s.numbers("light.position", 3, 3, -1e6, 1e6, "required", "world position").draws(-5, 5).edge({0, 1e-3});

        s.object("surface", true, "the solid layer's height field");
        s.choice("surface.heights", {"stones", "flat", "walls", "file"}, "stones",
                 "stones; one height everywhere; one-texel walls; or an image's red channel")
            .explore_choices({"stones", "flat", "walls"});
        s.text("surface.height_map", "required", "the image (a path), square, 4 to 4096 texels a side")
            .when("surface.heights", {"file"});
        s.integer("surface.map_size", 4, 4096, 256, "texels a side").explore_at_most(1024).edge({4, 5, 64, 255, 256});
        s.integer("surface.stones", 1, 64, 5, "stones a side (a jittered Voronoi grid)");
        s.integer("surface.seed", 0, 1 << 30, 1, "the stones' layout");
        s.number("surface.depth", 0, 10, 0.08, "the layer's depth in texture coordinates").draws(0, 0.5).edge({1e-6, 1});
        s.number("surface.uv_per_unit", 1e-3, 1e3, 1.0, "texture coordinates per world unit").draws(0.1, 10).log();
        s.number("surface.flat_height", 0, 1, 0.5, "the one height of a flat field").when("surface.heights", {"flat"});
        s.integer("surface.wall_spacing", 2, 4096, 16, "texels between walls")
            .at_most("surface.map_size").when("surface.heights", {"walls"});

        s.object("search", false, "the intersection search (Sec. 3); normal mapping reads none of it");
        s.integer("search.linear_steps", 1, 512, 16, "equal steps until the ray has crossed").explore_at_most(128)
            .edge({1, 2, 3, 4, 7, 8, 16, 31, 32});
        s.integer("search.binary_steps", 0, 32, 6, "halvings of the last step").edge({0, 1, 2, 3});
        s.boolean("search.secant", true, "end on the zero of the line through the bracket's ends");
        s.integer("search.min_linear_steps", 0, 512, 0,
                  "the step count scaled by the view angle from this many head-on (0: off)")
            .at_most("search.linear_steps").when("technique", {"relief"});

        s.object("liquid", true, "the translucent medium").when("technique", two_layer);
        s.number("liquid.depth", 1e-4, 10, 0.1, "its box's depth in texture coordinates").draws(1e-3, 0.5);
        s.number("liquid.ior", 1e-3, 10, 1.33, "index of refraction relative to air (below 1: thinner than air, the view ray totally reflected past an angle)")
            .draws(0.5, 2.5)
            .edge({1, 1.0001});
        s.integer("liquid.drops", 0, 1000, 14, "drops on the film").explore_at_most(100);
        s.integer("liquid.seed", 0, 1 << 30, 2, "the drops' layout");
        s.number("liquid.level", 0, 1, 0.25, "the film between the drops (0: none above the floor)");
        s.number("liquid.min_radius", 1e-3, 0.5, 0.04, "least drop radius, texture coordinates");
        s.number("liquid.max_radius", 1e-3, 0.5, 0.11, "largest drop radius").at_least("liquid.min_radius");
        s.number("liquid.min_peak", 0, 1, 0.55, "least height of a drop's apex").at_least("liquid.level");
        s.number("liquid.max_peak", 0, 1, 0.95, "largest height of a drop's apex").at_least("liquid.min_peak");
        s.numbers("liquid.half_distance", 3, 3, 1e-6, 1e6, "required",
                  "world distance over which each channel keeps half its light (Eq. 1)")
            .draws(0.01, 10).log().when("technique", {"absorption"});
        s.integer("liquid.max_crossings", 1, 16, 4, "boundaries of the medium a light ray is followed through")
            .edge({1, 2, 16}).when("technique", occluding);
        s.number("liquid.shadow_bias", 0, 1, 0.02, "the light ray's start above the hit, in the layer's heights")
            .draws(0, 0.1).when("technique", occluding);

        s.object("reflections", false, "planar local reflections").when("technique", two_layer);
        s.boolean("reflections.planar", false, "refracted and reflected rays against a plane instead of searched");
        s.number("reflections.plane_height", 0, 1, 0.5, "the plane's height in the solid layer's units");

        s.object("environment", true, "the sky cube map").when("technique", two_layer);
        s.integer("environment.size", 1, 2048, 64, "texels a face side").explore_at_most(256).edge({1, 2, 64});
        s.numbers("environment.sun_direction", 3, 3, -1e6, 1e6, nlohmann::json::array({0.4, 0.3, 0.6}),
                  "towards the sun (not the zero vector)")
            .draws(-1, 1);
        s.number("environment.sun_radiance", 0, 65000, 30.0, "the sun disc's radiance").draws(0, 100);
        s.number("environment.sun_radius_deg", 0, 90, 2.0, "the sun disc's angular radius").draws(0, 10);

        s.object("bloom", false, "light blooming (Sec. 3.2), frames of at least 8x8").when("technique", two_layer);
        s.boolean("bloom.enabled", true, "the blooming passes after the scene's");
        s.number("bloom.threshold", 0, 65000, 1.0, "radiance above which light blooms").draws(0, 4);
        s.number("bloom.strength", 0, 1000, 1.0, "how much of the blur is added back").draws(0, 4);

        s.object("shading", true, "lighting terms");
        s.number("shading.ambient", 0, 10, 0.15, "ambient term").draws(0, 1);
        s.number("shading.specular", 0, 100, 0.35, "Blinn-Phong specular weight").draws(0, 2);
        s.number("shading.liquid_specular", 0, 1000, 0.0, "the medium's highlight").draws(0, 4).when("technique", two_layer);
        s.boolean("shading.intensify", false, "Phong-specular intensification (Sec. 3.2)").when("technique", two_layer);
        return s;
    }();
    return space;
}

}  // namespace st
