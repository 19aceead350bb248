#!/usr/bin/env python3
"""Writes the built-in scenes/profile-*.json: rendering with diffusion
profiles (Donner and Jensen Sec. 3, docs/profile-rendering.md). One function
per figure of the paper; materials the paper gives are cited, the rest are
ours and say so in their descriptions. Rerun after editing; commit the output.
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "scenes")

EXACT = {"coverage_mismatch": 0, "min_identical_fraction_float": 1,
         "rationale": "Every operation repeats llvmpipe's; bit identity is expected."}


def write(name, scene):
    scene = dict(scene)
    scene.setdefault("criteria", EXACT)
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


def load_layers(name):
    with open(os.path.join(HERE, "..", "materials", name)) as f:
        return json.load(f)


def ground_truth():
    write("profile-slab-edge", {
        "kind": "profile",
        "description": "The ground truth of the gather (Donner and Jensen Sec. 3): a flat, semi-infinite slab of "
                       "Jensen et al.'s skin 1 (their Table, sigma_s' and sigma_a per mm, eta 1.3), lit straight on "
                       "by a spot and beyond a shadow edge and seen from 30 degrees; its exact image is the 2D "
                       "convolution of that light with the multipole profile (app/profile_exact.h, `sweep profile`).",
        "width": 320, "height": 240,
        "material": {"model": "multipole", "sigma_a": [0.032, 0.17, 0.48], "sigma_s": [0.74, 0.88, 1.01],
                     "g": 0.0, "eta": 1.3},
        "geometry": {"shape": "slab", "size_mm": 120, "texture_size": 256},
        "view": {"angle_deg": 30, "azimuth_deg": -90, "distance_mm": 170, "fov_deg": 45},
        "light": {"direction": [0, 0, 1], "irradiance": [3.0],
                  "spot": {"centre_mm": [-20, 0], "radius_mm": 6}, "edge": {"normal": [1, 0], "offset_mm": 10}},
        "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
    })


def figure4_parchment():
    # The paper gives only the thickness (about four mean free paths).
    for model, extra in (("dipole", {}), ("multipole", {}), ("mc", {"photons": 200000, "seed": 1, "mc_r_max_mm": 10})):
        description = {
            "dipole": "Figure 4 of Donner and Jensen: parchment about 1 mm and four mean free paths thick "
                      "(sigma_a 0.1, sigma_s 3.9 per mm, g 0, eta 1.5; the paper gives only the thickness), lit "
                      "from behind, half of it shadowed by a straight edge, its profile from the dipole (one source "
                      "pair). Total transmittance: dipole 0.177, multipole 0.220, Monte "
                      "Carlo 0.217 (`shadertwin slab`); the paper reports 0.033, 0.226 and 0.215.",
            "multipole": "Figure 4 of Donner and Jensen: parchment about 1 mm and four mean free paths thick "
                         "(sigma_a 0.1, sigma_s 3.9 per mm, g 0, eta 1.5; the paper gives only the thickness), "
                         "lit from behind, half of it shadowed by a straight edge, its profile from the multipole. "
                         "Total transmittance: dipole 0.177, multipole 0.220, Monte Carlo 0.217 (`shadertwin "
                         "slab`); the paper reports 0.033, 0.226 and 0.215.",
            "mc": "Figure 4 of Donner and Jensen: parchment about 1 mm and four mean free paths thick (sigma_a "
                  "0.1, sigma_s 3.9 per mm, g 0, eta 1.5; the paper gives only the thickness), lit from behind, "
                  "half of it shadowed by a straight edge, its profile from Monte Carlo photon tracing (200000 "
                  "photons, bins of 0.025 mm). Total transmittance: dipole 0.177, multipole 0.220, Monte Carlo "
                  "0.217 (`shadertwin slab`); the paper reports 0.033, 0.226 and 0.215.",
        }[model]
        material = {"model": model, "sigma_a": [0.1], "sigma_s": [3.9], "g": 0.0, "eta": 1.5, "thickness_mm": 1.0}
        material.update(extra)
        write("profile-parchment-" + model, {
            "kind": "profile", "description": description, "width": 320, "height": 240,
            "material": material,
            "geometry": {"shape": "slab", "size_mm": 30, "texture_size": 256},
            "view": {"angle_deg": 20, "azimuth_deg": -90, "distance_mm": 45, "fov_deg": 45},
            "light": {"direction": [0.2, 0.1, -1], "irradiance": [4.0],
                      "edge": {"normal": [1, 0.3], "offset_mm": -2}},
            "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
        })


def figure8_skin():
    # Table 3 (Tuchin 2000): epidermis, upper dermis, bloody dermis (semi-infinite).
    table3 = load_layers("skin-table3.json")
    head = {"shape": "ellipsoid", "radii_mm": [75, 90, 110], "segments": 96, "texture_size": 512}
    view = {"angle_deg": 80, "azimuth_deg": -90, "distance_mm": 420, "fov_deg": 45}
    for name, light, what in (("front", [-0.5, -1.0, 0.6], "lit from the front left"),
                              ("back", [0.8, 0.9, 0.25], "lit from behind and to the right, so that the light "
                                                         "bleeds past the terminator into the shadowed side")):
        write("profile-skin-head-" + name, {
            "kind": "profile",
            "description": "Figure 8 of Donner and Jensen: three-layer skin with Table 3's parameters (epidermis "
                           "0.03 mm, upper dermis 0.05 mm, semi-infinite bloody dermis; materials/skin-table3.json) "
                           "combined in frequency space, on a head-sized ellipsoid (150 x 180 x 220 mm) " + what +
                           "; the layout's seam faces away from the camera.",
            "width": 320, "height": 320,
            "material": {"model": "layered", "layers": table3},
            "geometry": head, "view": view,
            "light": {"direction": light, "irradiance": [3.0]},
            "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
        })
    write("profile-skin-head-textured", {
        "kind": "profile",
        "description": "Figure 8's lower row: the front-lit Table 3 head textured as Sec. 3.1 says: an albedo map "
                       "(ours: 400 freckles of 1.5 mm) convolved with the layered profile on the host, normalised to "
                       "a white mean, scaling the diffused light (scene/profile_albedo.h).",
        "width": 320, "height": 320,
        "material": {"model": "layered", "layers": table3},
        "geometry": head, "view": view,
        "light": {"direction": [-0.5, -1.0, 0.6], "irradiance": [3.0]},
        "albedo": {"pattern": "freckles", "count": 400, "radius_mm": 1.5, "strength": [0.35, 0.5, 0.6], "seed": 1},
        "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
    })
    # The ear: the same upper layers over a bloody dermis of finite thickness,
    # so that light crosses it (the paper's back-lit ear).
    ear = [dict(l) for l in table3]
    ear[-1]["thickness"] = 1.5
    write("profile-skin-ear-back", {
        "kind": "profile",
        "description": "Figure 8's back-lit ear: Table 3's epidermis and upper dermis over 1.5 mm of bloody dermis "
                       "(ours: Table 3 makes it semi-infinite; the ear's is finite so that light crosses it), on a "
                       "40 mm sheet bent through 140 degrees, lit from behind; the light seen is the layered "
                       "stack's transmittance.",
        "width": 320, "height": 240,
        "material": {"model": "layered", "layers": ear},
        "geometry": {"shape": "sheet", "size_mm": 40, "bend_deg": 140, "segments": 64, "texture_size": 256},
        "view": {"angle_deg": 25, "azimuth_deg": -90, "distance_mm": 70, "fov_deg": 45},
        "light": {"direction": [0.2, 0.3, -1.0], "irradiance": [6.0]},
        "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
    })


def figure7_marble():
    # Jensen et al. 2001's marble: sigma_s' and sigma_a per mm, eta 1.5.
    for roughness in (0.1, 0.5, 1.0):
        write("profile-marble-rough-%.1f" % roughness, {
            "kind": "profile",
            "description": "Figure 7 of Donner and Jensen: marble (Jensen et al. 2001: sigma_s' 2.19, 2.62, 3.00, "
                           "sigma_a 0.0021, 0.0041, 0.0071 per mm, eta 1.5) with surface roughness %.1f: the rough "
                           "boundary's rho_dt lets less light in and out (Eq. 26). Semi-infinite, so the dipole is "
                           "the whole multipole. An 80 x 80 x 120 mm ellipsoid lit from the front left." % roughness,
            "width": 240, "height": 320,
            "material": {"model": "dipole", "sigma_a": [0.0021, 0.0041, 0.0071], "sigma_s": [2.19, 2.62, 3.00],
                         "g": 0.0, "eta": 1.5, "roughness": roughness},
            "geometry": {"shape": "ellipsoid", "radii_mm": [40, 40, 60], "segments": 96, "texture_size": 256},
            "view": {"angle_deg": 75, "azimuth_deg": -90, "distance_mm": 330, "fov_deg": 35},
            "light": {"direction": [-0.6, -1.0, 0.7], "irradiance": [3.0]},
            "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
        })


def figure5_jade():
    # Ours (the paper gives none): jade absorbs all but green; paint is a thin,
    # strongly scattering white layer, sprayed on both faces.
    jade = {"sigma_a": [0.45, 0.02, 0.35], "sigma_s": [2.0, 2.0, 2.0], "g": 0.0, "eta": 1.6, "thickness": 4.0}
    paint = {"sigma_a": [0.01, 0.01, 0.01], "sigma_s": [60.0, 60.0, 60.0], "g": 0.0, "eta": 1.5, "thickness": 0.05}
    painted = [paint, dict(jade, eta=1.6 / 1.5), dict(paint, eta=1.5 / 1.6)]
    lights = {"front": [0.3, -0.4, 1.0], "back": [0.1, 0.2, -1.0]}
    power = {"front": 3.0, "back": 10.0}
    for painted_too in (False, True):
        for side, light in lights.items():
            name = "profile-jade-" + ("paint-" if painted_too else "") + side
            if painted_too:
                material = {"model": "layered", "layers": painted}
                what = "sprayed on both faces with 0.05 mm of white paint (sigma_s 60 per mm), the stack combined " \
                       "in frequency space"
            else:
                material = {"model": "multipole", "sigma_a": jade["sigma_a"], "sigma_s": jade["sigma_s"],
                            "g": 0.0, "eta": 1.6, "thickness_mm": 4.0}
                what = "unpainted, its profile from the multipole"
            write(name, {
                "kind": "profile",
                "description": "Figure 5 of Donner and Jensen: a 4 mm jade-like panel (ours: sigma_a 0.45, 0.02, "
                               "0.35, sigma_s 2 per mm, eta 1.6) " + what + ", " + side + "-lit. Paint whitens "
                               "what is reflected and dims what enters; what crosses stays green.",
                "width": 320, "height": 240,
                "material": material,
                "geometry": {"shape": "sheet", "size_mm": 40, "bend_deg": 90, "segments": 64, "texture_size": 256},
                "view": {"angle_deg": 25, "azimuth_deg": -90, "distance_mm": 75, "fov_deg": 45},
                "light": {"direction": light, "irradiance": [power[side]]},
                "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
            })


def figure6_leaf():
    # Ours, after Hemenger 1977 (the paper's absorption data, Fukshansky et al.
    # 1993, are not given): a thick absorbing palisade layer over a thin,
    # strongly scattering spongy one. `slab --layers`: R 0.37/0.70/0.30 from
    # the front, 0.72/0.79/0.70 from the back; T 0.036/0.140/0.018 and
    # 0.039/0.142/0.021, nearly the same either way.
    leaf = [{"sigma_a": [1.2, 0.12, 2.0], "sigma_s": [20.0, 20.0, 20.0], "g": 0.0, "eta": 1.45, "thickness": 0.2},
            {"sigma_a": [0.2, 0.05, 0.3], "sigma_s": [120.0, 120.0, 120.0], "g": 0.0, "eta": 1.0, "thickness": 0.08}]
    for name, light, flip, what in (
            ("front", [0.3, -0.3, 1.0], False, "lit from the front (its palisade side)"),
            ("back", [0.2, 0.3, -1.0], False, "lit from behind: what is seen is the stack's transmittance"),
            ("underside", [0.3, -0.3, 1.0], True, "turned over (`flip`): the spongy side faces the light and the "
                                                  "camera, and reflects far more")):
        material = {"model": "layered", "layers": leaf}
        if flip:
            material["flip"] = True
        write("profile-leaf-" + name, {
            "kind": "profile",
            "description": "Figure 6 of Donner and Jensen: a two-layer leaf (ours: 0.2 mm absorbing palisade over "
                           "0.08 mm of strongly scattering spongy mesophyll), the stack combined in frequency space, "
                           "on a 30 mm sheet bent through 40 degrees, " + what + ". Its veins are a thickness map "
                           "used as a displacement (0.1 mm), as the paper does; the colour is the layers', no texture.",
            "width": 320, "height": 240,
            "material": material,
            "geometry": {"shape": "sheet", "size_mm": 30, "bend_deg": 40, "segments": 32, "texture_size": 512,
                         "thickness_map": {"height_mm": 0.1, "vein_spacing_mm": 4, "vein_width_mm": 0.15}},
            "view": {"angle_deg": 20, "azimuth_deg": -90, "distance_mm": 48, "fov_deg": 45},
            "light": {"direction": light, "irradiance": [10.0 if name == "back" else 3.0]},
            "gather": {"pattern": "importance", "samples": 64, "table_size": 256},
        })


def main():
    ground_truth()
    figure4_parchment()
    figure5_jade()
    figure6_leaf()
    figure7_marble()
    figure8_skin()


if __name__ == "__main__":
    main()
