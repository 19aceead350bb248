// profile_space.cpp: the fields of a "profile" scene (rendering with
// diffusion profiles, Donner and Jensen Sec. 3; scene/profile_scene.cpp
// builds it), with their domains. Lengths in mm. Where a reader keeps its
// settings in a struct whose defaults other code uses too (GatherSettings,
// ProfileMaterial, ProfileShape, AlbedoMap, ThicknessMap), the declared
// default is the struct's. `quality` and `quality_budget` are not here:
// shadertwin's resolver (app/quality/profile_quality.h) takes them out of the scene
// before the builder reads it.
#include "scene/profile_scene.h"
#include "scene/scene_spaces.h"

namespace st {

const ParamSpace& profile_space() {
    static const ParamSpace space = [] {
        const ProfileMaterial material;
        const ProfileShape shape;
        const ThicknessMap veins;
        const AlbedoMap freckles;
        const GatherSettings gather;
        const std::vector<std::string> generated = {"slab", "sheet", "ellipsoid"};
        const std::vector<std::string> curved = {"sheet", "ellipsoid"};
        ParamSpace s("profile");
        s.include(common_space());

        s.object("material", true, "what scatters: one slab, or a stack of layers");
        s.choice("material.model", {"dipole", "multipole", "layered", "mc"}, "multipole",
                 "the profile: dipole or multipole (one slab), frequency-space KM of a stack, or Monte Carlo");
        s.object("material.layers", false, "a stack, top first, in the layer-file format of `slab --layers`", 1, 64)
            .opaque_object();
        s.text("material.layers_file", nullptr, "a layer file (a path), instead of `layers`");
        // One slab, where neither `layers` nor `layers_file` is given (the
        // explorer changes them only in a scene that has them: it never
        // adds a slab's optics to a stack):
        s.numbers("material.sigma_a", 1, 3, 1e-9, 1e6, "required",
                  "absorption per mm, one value or three (R, G, B); one slab's (without `layers`)")
            .draws(1e-3, 10).log().only_if_present();
        s.numbers("material.sigma_s", 1, 3, 0, 1e6, "required",
                  "scattering per mm, one value or three (R, G, B); one slab's")
            .draws(0.1, 100).log().edge({0}).only_if_present();
        s.number("material.g", -0.99, 0.99, 0.0, "one slab's mean cosine of scattering").edge({0}).only_if_present();
        s.number("material.eta", 1, 3, 1.3, "one slab's index of refraction").edge({1, 1.3}).only_if_present();
        s.number("material.thickness_mm", 1e-4, 1e4, nullptr, "one slab's thickness (absent: semi-infinite)")
            .draws(0.05, 50).log().only_if_present();
        s.number("material.roughness", 0, 2, 0.0,
                 "one slab's RMS slope of a rough top (0: smooth; below 0.05 refused, as for every layer's)")
            .edge({0, 0.05, 2})
            .only_if_present();
        s.boolean("material.flip", false, "the stack seen from its other side (not with a semi-infinite layer)");
        s.integer("material.max_dipole_pairs", 1, 1 << 20, material.max_dipole_pairs,
                  "the most dipole pairs per side the multipole may take to converge")
            .when("material.model", {"multipole"}).explore_at_most(10000).edge({1, 2});
        s.integer("material.photons", 1000, 100000000, int(material.photons), "Monte Carlo photons per channel")
            .when("material.model", {"mc"}).explore_at_most(200000).log();
        s.integer("material.seed", 0, 1 << 30, int(material.seed), "the photons' random stream")
            .when("material.model", {"mc"});
        s.number("material.mc_r_max_mm", 1e-3, 1e4, material.mc_r_max, "the radial bins' reach")
            .when("material.model", {"mc"}).draws(1, 100).log();

        s.object("geometry", true, "the shape, and the texture-space targets' size");
        s.choice("geometry.shape", {"slab", "sheet", "ellipsoid", "mesh"}, shape.kind,
                 "a square in z = 0 facing +z, that square bent about y, an ellipsoid, or your own mesh")
            .explore_choices(generated);  // a mesh needs a file the explorer cannot make up
        s.text("geometry.mesh_file", "required",
               "a Wavefront OBJ file (a path) whose every face corner has texture coordinates in [0, 1]")
            .when("geometry.shape", {"mesh"});
        s.number("geometry.size_mm", 1e-3, 1e5, shape.size_mm, "the square's side (an ellipsoid reads and ignores it)")
            .when("geometry.shape", generated).draws(1, 200).log();
        s.number("geometry.bend_deg", 0, 340, shape.bend_deg, "the arc the sheet's side spans (past 180 its arms face)")
            .when("geometry.shape", {"sheet"}).edge({0, 180, 340});
        s.numbers("geometry.radii_mm", 3, 3, 1e-3, 1e5, "required", "the ellipsoid's semi-axes")
            .when("geometry.shape", {"ellipsoid"}).draws(1, 100).log();
        s.number("geometry.seam_azimuth_deg", -360, 360, shape.seam_azimuth_deg,
                 "azimuth of the layout's seam (u = 0 and 1)")
            .when("geometry.shape", {"ellipsoid"});
        s.integer("geometry.segments", 4, 1024, shape.segments, "quads around (half as many pole to pole)")
            .when("geometry.shape", curved).explore_at_most(256).edge({4, 5});
        s.object("geometry.thickness_map", false, "a leaf's veins as a displacement along the normal")
            .when("geometry.shape", {"slab", "sheet"});
        s.number("geometry.thickness_map.height_mm", 1e-6, 1e3, "required", "displacement at the map's 1")
            .draws(1e-3, 1).log();
        s.number("geometry.thickness_map.vein_spacing_mm", 1e-3, 1e5, veins.vein_spacing_mm, "between side veins")
            .draws(0.5, 20).log();
        s.number("geometry.thickness_map.vein_width_mm", 1e-4, 1e4, veins.vein_width_mm, "a vein's Gaussian width")
            .draws(0.05, 2).log();
        s.integer("geometry.texture_size", 4, 4096, ProfileSceneSpec{}.texture_size,
                  "the texture-space targets' side, texels (an albedo map's convolution grows as its square or faster)")
            .explore_at_most(256).edge({4, 5, 64});

        s.object("view", true, "the camera about the origin (the slab's centre)");
        s.number("view.angle_deg", 0, 89, 30.0, "from +z, degrees").edge({0, 1e-4, 60, 89});
        s.number("view.azimuth_deg", -360, 360, -90.0, "around z, degrees").edge({0, -90, 90});
        s.number("view.distance_mm", 1e-3, 1e6, nullptr,
                 "from the origin (default: twice the shape's largest extent); it must see the whole shape")
            .draws(10, 1000).log();
        s.number("view.fov_deg", 1, 120, 45.0, "vertical field of view, degrees");

        s.object("light", true, "a directional light; with a spot or an edge, only they are lit (box-filtered)");
        s.numbers("light.direction", 3, 3, -1e6, 1e6, "required", "towards the light (not the zero vector)")
            .draws(-1, 1);
        s.numbers("light.irradiance", 1, 3, 0, 1e6, "required", "one value or three (R, G, B)").draws(0, 10).edge({0});
        s.object("light.spot", false, "only a disc is lit");
        s.numbers("light.spot.centre_mm", 2, 2, -1e6, 1e6, "required", "its centre in x, y").draws(-50, 50);
        s.number("light.spot.radius_mm", 1e-6, 1e6, "required", "its radius").draws(0.1, 50).log();
        s.object("light.edge", false, "only the side beyond a shadow edge is lit");
        s.numbers("light.edge.normal", 2, 2, -1e6, 1e6, "required", "the edge's normal in x, y (not the zero vector)")
            .draws(-1, 1);
        s.number("light.edge.offset_mm", -1e6, 1e6, "required", "the edge's offset along it").draws(-50, 50).edge({0});

        s.object("albedo", false, "Sec. 3.1 texturing, convolved with the profile (absent: white); generated shapes only");
        s.choice("albedo.pattern", {"freckles"}, "freckles", "the map");
        s.integer("albedo.count", 1, 100000, freckles.count, "freckles").explore_at_most(2000).log();
        s.number("albedo.radius_mm", 1e-3, 1e4, freckles.radius_mm, "a freckle's Gaussian radius").draws(0.01, 30).log();
        s.numbers("albedo.strength", 3, 3, 0, 0.95, "required", "how much of each channel a freckle's centre takes away");
        s.integer("albedo.seed", 0, 1 << 30, int(freckles.seed), "the freckles' layout");

        s.object("gather", false, "the gather from the camera");
        s.choice("gather.pattern", {"importance", "disk"}, gather.pattern,
                 "radii by the profile's inverse CDF on a Vogel spiral, or uniform over the reach");
        s.integer("gather.samples", 1, kMaxGatherSamples, gather.samples, "samples per pixel")
            .explore_at_most(1024).edge({1, 2, 3, 64});
        s.integer("gather.table_size", 2, 16384, gather.table_size,
                  "entries of the R(r) and T(r) tables (each a texture row: llvmpipe's widest is 16384)")
            .explore_at_most(8192).edge({2, 3, 256});
        s.number("gather.tail_fraction", 1e-9, 0.5, gather.tail_fraction, "the share of the profile the reach may leave out")
            .log().edge({1e-3});
        return s;
    }();
    return space;
}

}  // namespace st
