#!/usr/bin/env python3
"""Writes the conformance scenes (scenes/conformance-*.json): the shading
runtime's behaviours pinned against llvmpipe, each a small program from
glsl/conformance/ on a few triangles. Run from anywhere; it rewrites the
files in place. After adding scenes, run `shadertwin compare` on them and
`shadertwin golden update <new scenes>`."""
import json
import os

SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes")
def quad(x0,y0,x1,y1,u0,v0,u1,v1,cols=None, skew=3.0):
    # a skewed quad in two triangles, so edges cut through blocks
    P=[[x0+skew,y0],[x1,y0+skew],[x1-skew,y1],[x0,y1-skew]]
    U=[[u0,v0],[u1,v0],[u1,v1],[u0,v1]]
    C=cols or [[1,1,1,1],[0.5,1,0.75,1],[1,0.25,1,1],[0.8,0.6,0.4,1]]
    t=[]
    for a,b,c in ((0,1,2),(0,2,3)):
        t.append({"positions":[P[a],P[b],P[c]],"colours":[C[a],C[b],C[c]],"uvs":[U[a],U[b],U[c]]})
    return t
def write(name, d):
    c=d.setdefault("criteria",{})
    c["min_identical_fraction_float"]=1
    c.setdefault("rationale","A conformance scene: the twin must give llvmpipe's bits in every pixel.")
    open(os.path.join(SCENES, f"conformance-{name}.json"),"w").write(json.dumps(d,indent=1)+"\n")
tex=lambda s,**k: dict({"sampler":s},**k)
write("loop-exit",{"kind":"conformance",
 "description":"A search loop whose lanes leave at different passes (alpha test per step), sampling an rgba8 texture inside the loop.",
 "width":64,"height":64,"fragment":"loop_exit",
 "uniforms":[{"name":"steps","int":24},{"name":"dir","vec2":[0.013,0.021]},{"name":"threshold","float":0.8}],
 "textures":[tex("tex",format="rgba8",filter="linear",wrap="repeat",width=16,height=16,pattern="noise",seed=3)],
 "triangles":quad(1.5,2.25,62.5,61.75,-0.2,-0.1,1.3,1.2)})
write("branch-texture",{"kind":"conformance",
 "description":"Texture reads on both sides of a divergent branch: rgba8 linear repeat on one side, rgba32f nearest clamp on the other.",
 "width":64,"height":64,"fragment":"branch_texture",
 "uniforms":[{"name":"split","float":0.8}],
 "textures":[tex("tex_a",format="rgba8",filter="linear",wrap="repeat",width=8,height=8,pattern="noise",seed=5),
             tex("tex_b",format="rgba32f",filter="nearest",wrap="clamp",width=12,height=10,pattern="noise",seed=6)],
 "triangles":quad(2.5,1.5,61.5,62.5,-0.1,-0.1,1.1,1.1)})
write("derivatives",{"kind":"conformance",
 "description":"dFdx, dFdy and fwidth of computed values: a polynomial, its square and a step function.",
 "width":64,"height":64,"fragment":"derivatives",
 "uniforms":[{"name":"scale","float":7.0}],
 "triangles":quad(0.5,3.5,63.5,60.5,-0.3,0.1,1.7,1.4)})
write("discard",{"kind":"conformance",
 "description":"discard on a pattern and inside a loop, over a depth-tested background triangle: discarded pixels write neither colour nor depth.",
 "width":64,"height":64,"fragment":"discard","depth_test":True,"clear_colour":[0.1,0.2,0.3,1],
 "uniforms":[{"name":"steps","int":12}],
 "triangles":quad(1.5,2.5,62.5,61.5,0.05,0.1,1.0,1.2)})
write("non-finite",{"kind":"conformance",
 "description":"A shader writing +-infinity and NaN (x / 0, 0 / 0) and comparing against NaN; both backends must write the same bits.",
 "width":64,"height":64,"fragment":"non_finite",
 "uniforms":[{"name":"zero","float":0.0}],
 "criteria":{"nonfinite":"identical","rationale":"The shader divides by zero on purpose: every channel is +-inf or NaN somewhere. Non-finite values are allowed where both backends write the same bits."},
 "triangles":quad(0,0,64,64,0.0,0.0,1.0,1.0,skew=0.0)})
write("loop-budget",{"kind":"conformance",
 "description":"The shared budget of 65535 loop passes per 8-lane vector: a covered pixel and an uncovered helper lane each loop 100000 times, so the short loop after runs once in their vectors only.",
 "width":64,"height":64,"fragment":"loop_budget",
 "uniforms":[{"name":"long_steps","int":100000},{"name":"short_steps","int":40},
             {"name":"slow_a","vec2":[21,30]},{"name":"slow_b","vec2":[10,2]}],
 "triangles":quad(1.5,2.5,62.5,61.5,0,0,1,1)})

def strips(scales, lod_cols=False):
    # 8 vertical strips, each a skewed quad with its own uv scale (so its own LOD)
    tris=[]
    n=len(scales)
    for i,s in enumerate(scales):
        x0=i*64/n+0.25; x1=(i+1)*64/n-0.25
        y0=1.5; y1=62.5
        u0=0.1*i; v0=0.05*i
        du=s*(x1-x0)/16; dv=s*(y1-y0)/16*1.13
        P=[[x0,y0],[x1,y0+1.5],[x1,y1],[x0+0.5,y1-1.0]]
        U=[[u0,v0],[u0+du,v0+0.07*s],[u0+du*1.05,v0+dv],[u0-0.03*s,v0+dv*0.97]]
        if lod_cols:
            C=[[0,1,1,1],[0.15,1,1,1],[1,1,1,1],[0.85,1,1,1]]
        else:
            C=[[1,1,1,1],[0.9,1,0.8,1],[1,0.85,1,1],[0.95,0.9,1,1]]
        for a,b,c in ((0,1,2),(0,2,3)):
            tris.append({"positions":[P[a],P[b],P[c]],"colours":[C[a],C[b],C[c]],"uvs":[U[a],U[b],U[c]]})
    return tris
scales=[0.4,0.9,1.0,1.7,2.0,3.3,6.0,13.0]
for fmt in ["rgba8","rgba32f","rgba16f","r32f"]:
    for mf in ["nearest_mipmap_nearest","linear_mipmap_nearest","nearest_mipmap_linear","linear_mipmap_linear"]:
        mag = "linear" if mf.startswith("linear") else "nearest"
        short = mf.replace("_mipmap_","-mip-").replace("nearest","n").replace("linear","l")
        write(f"mip-{fmt}-{mf.replace('_mipmap_','-mip-').replace('_','-')}",{"kind":"conformance",
          "description":f"texture() with implicit LOD on a {fmt} mip chain (16x16, distinct levels), min {mf}, mag {mag}, repeat: eight strips from magnified to minified 13x.",
          "width":64,"height":64,"fragment":"sample_implicit",
          "textures":[{"sampler":"tex","format":fmt,"min_filter":mf,"mag_filter":mag,"wrap":"repeat","width":16,"height":16,"pattern":"noise","seed":11,"mipmaps":"distinct"}],
          "triangles":strips(scales)})
for fmt in ["rgba8","rgba32f"]:
    for wrap in ["clamp","mirrored_repeat"]:
        write(f"mip-{fmt}-wrap-{wrap.replace('_','-')}",{"kind":"conformance",
          "description":f"texture() with implicit LOD, {fmt} 12x10 (npot) box-filtered chain, linear_mipmap_linear, wrap {wrap}.",
          "width":64,"height":64,"fragment":"sample_implicit",
          "textures":[{"sampler":"tex","format":fmt,"min_filter":"linear_mipmap_linear","mag_filter":"linear","wrap":wrap,"width":12,"height":10,"pattern":"noise","seed":12,"mipmaps":"box"}],
          "triangles":strips([s*1.3 for s in scales])})
for fmt in ["rgba8","rgba32f"]:
    for mf in ["linear_mipmap_nearest","linear_mipmap_linear"]:
        write(f"mip-lod-{fmt}-{mf.replace('_mipmap_','-mip-').replace('_','-')}",{"kind":"conformance",
          "description":f"textureLod() with a per-pixel LOD from -1.5 to 5.5 across level boundaries, {fmt} 16x16 distinct levels, min {mf}.",
          "width":64,"height":64,"fragment":"sample_lod",
          "uniforms":[{"name":"lod_min","float":-1.5},{"name":"lod_max","float":5.5}],
          "textures":[{"sampler":"tex","format":fmt,"min_filter":mf,"mag_filter":"linear","wrap":"repeat","width":16,"height":16,"pattern":"noise","seed":13,"mipmaps":"distinct"}],
          "triangles":strips([1.0]*8, lod_cols=True)})
# min != mag
for fmt in ["rgba8","rgba32f"]:
    for mn,mg in [("linear_mipmap_linear","nearest"),("nearest_mipmap_nearest","linear"),("linear","nearest"),("nearest","linear"),("nearest_mipmap_linear","linear")]:
        tag=f"{mn.replace('_mipmap_','-mip-').replace('_','-')}-mag-{mg}"
        write(f"minmag-{fmt}-{tag}",{"kind":"conformance",
          "description":f"texture() with min {mn} and mag {mg} on a {fmt} 16x16 chain: the switch between magnified and minified quads (per quad on the 8-bit path, per 8-lane vector on the float path).",
          "width":64,"height":64,"fragment":"sample_implicit",
          "textures":[{"sampler":"tex","format":fmt,"min_filter":mn,"mag_filter":mg,"wrap":"repeat","width":16,"height":16,"pattern":"noise","seed":21,"mipmaps":"distinct"}],
          "triangles":strips([0.5,0.8,0.95,1.02,1.1,1.6,2.4,5.0])})
        write(f"minmag-lod-{fmt}-{tag}",{"kind":"conformance",
          "description":f"textureLod() from -1 to 3 with min {mn} and mag {mg} on a {fmt} 16x16 chain (rgba8 leaves the 8-bit path here).",
          "width":64,"height":64,"fragment":"sample_lod",
          "uniforms":[{"name":"lod_min","float":-1.0},{"name":"lod_max","float":3.0}],
          "textures":[{"sampler":"tex","format":fmt,"min_filter":mn,"mag_filter":mg,"wrap":"repeat","width":16,"height":16,"pattern":"noise","seed":22,"mipmaps":"distinct"}],
          "triangles":strips([0.7]*8, lod_cols=True)})
for fmt in ["rgba8","rgba32f"]:
    for mf in ["nearest_mipmap_nearest","linear_mipmap_linear"]:
        tag=mf.replace('_mipmap_','-mip-').replace('_','-')
        write(f"bias-{fmt}-{tag}",{"kind":"conformance",
          "description":f"texture() with a per-pixel bias from -2 to 3 on a {fmt} 16x16 chain, min {mf}.",
          "width":64,"height":64,"fragment":"sample_bias",
          "uniforms":[{"name":"lod_min","float":-2.0},{"name":"lod_max","float":3.0}],
          "textures":[{"sampler":"tex","format":fmt,"min_filter":mf,"mag_filter":"linear" if mf.startswith("linear") else "nearest","wrap":"repeat","width":16,"height":16,"pattern":"noise","seed":23,"mipmaps":"distinct"}],
          "triangles":strips([0.5,1.0,2.0,3.0,0.7,1.4,4.0,8.0], lod_cols=True)})
        write(f"grad-{fmt}-{tag}",{"kind":"conformance",
          "description":f"textureGrad() with per-pixel scaled derivatives on a {fmt} 16x16 chain, min {mf}.",
          "width":64,"height":64,"fragment":"sample_grad",
          "uniforms":[{"name":"grad_scale","float":12.0}],
          "textures":[{"sampler":"tex","format":fmt,"min_filter":mf,"mag_filter":"linear" if mf.startswith("linear") else "nearest","wrap":"repeat","width":16,"height":16,"pattern":"noise","seed":24,"mipmaps":"distinct"}],
          "triangles":strips([0.5,1.0,2.0,3.0,0.7,1.4,4.0,8.0], lod_cols=True)})
for fmt in ["rgba8","r32f","rgba16f"]:
    write(f"texel-fetch-{fmt}",{"kind":"conformance",
      "description":f"texelFetch() at levels -1 to 5 of a {fmt} 12x10 chain (4 levels), in and out of each level's bounds, and textureSize() of a per-pixel level.",
      "width":64,"height":64,"fragment":"texel_fetch",
      "textures":[{"sampler":"tex","format":fmt,"filter":"nearest","wrap":"repeat","width":12,"height":10,"pattern":"noise","seed":25,"mipmaps":"box"}],
      "triangles":strips([1.0]*8, lod_cols=True)})

# Cube maps: four quads, each sweeping the direction (u, v, 2b - 1) over a
# different range, so that every face, edge and corner is crossed, magnified
# (the first quads) and minified (the wide ranges).
def cube_quads(lod_cols=False):
    tris = []
    ranges = [(-1.3, 1.3, 0.0, 1.0), (-3.0, 3.0, 0.2, 0.8), (-0.9, 1.6, 1.0, 0.0), (-12.0, 12.0, 0.0, 1.0)]
    for q, (lo, hi, b0, b1) in enumerate(ranges):
        x0, y0 = (q % 2) * 32 + 0.5, (q // 2) * 32 + 0.5
        x1, y1 = x0 + 31.0, y0 + 31.0
        P = [[x0, y0], [x1, y0 + 0.75], [x1 - 0.5, y1], [x0 + 0.25, y1 - 0.5]]
        U = [[lo, lo], [hi, lo * 0.9], [hi, hi], [lo * 1.1, hi]]
        C = [[0.0, 0, b0, 1], [0.3, 0, b1, 1], [1.0, 0, b1, 1], [0.7, 0, b0, 1]] if lod_cols else \
            [[1, 1, b0, 1], [1, 1, b1, 1], [1, 1, b1, 1], [1, 1, b0, 1]]
        for a, b, c in ((0, 1, 2), (0, 2, 3)):
            tris.append({"positions": [P[a], P[b], P[c]], "colours": [C[a], C[b], C[c]], "uvs": [U[a], U[b], U[c]]})
    return tris

for fmt in ["rgba8", "rgba32f"]:
    for mf in ["linear", "nearest", "linear_mipmap_linear", "nearest_mipmap_nearest", "nearest_mipmap_linear"]:
        mag = "linear" if mf.startswith("linear") else "nearest"
        tag = mf.replace("_mipmap_", "-mip-").replace("_", "-")
        write(f"cube-{fmt}-{tag}", {"kind": "conformance",
          "description": f"texture() on a seamless {fmt} cube map (8x8 faces, distinct levels), min {mf}: every face, edge and corner, magnified and minified.",
          "width": 64, "height": 64, "fragment": "sample_cube",
          "textures": [{"sampler": "env", "cube": True, "format": fmt, "min_filter": mf, "mag_filter": mag, "wrap": "clamp",
                        "width": 8, "height": 8, "pattern": "noise", "seed": 31, "mipmaps": "distinct"}],
          "triangles": cube_quads()})
    write(f"cube-lod-{fmt}", {"kind": "conformance",
      "description": f"textureLod() from -1 to 4 on a seamless {fmt} cube map (8x8 faces, distinct levels), linear_mipmap_linear.",
      "width": 64, "height": 64, "fragment": "sample_cube_lod",
      "uniforms": [{"name": "lod_min", "float": -1.0}, {"name": "lod_max", "float": 4.0}],
      "textures": [{"sampler": "env", "cube": True, "format": fmt, "min_filter": "linear_mipmap_linear", "mag_filter": "linear",
                    "wrap": "clamp", "width": 8, "height": 8, "pattern": "noise", "seed": 32, "mipmaps": "distinct"}],
      "triangles": cube_quads(lod_cols=True)})

# Passes and targets: render to texture (RGBA16F and RGBA32F, levels,
# viewports, passes that keep what is there) and blend factors.
def overlapping(n=3, uv_scale=1.0, alpha=0.6):
    tris = []
    for k in range(n):
        ox, oy = 4 + k * 9.5, 3 + k * 7.25
        P = [[ox, oy], [ox + 40.5, oy + 5.0], [ox + 12.0, oy + 44.5]]
        U = [[0.1 * k, 0.0], [uv_scale, 0.2], [0.3, uv_scale]]
        C = [[1, 0.8, 0.6, alpha], [0.5, 1, 0.9, alpha * 0.5], [0.9, 0.4, 1, 1.0]]
        tris.append({"positions": P, "colours": C, "uvs": U})
    return tris

noise = lambda seed, fmt="rgba32f", **k: dict({"sampler": "tex", "format": fmt, "filter": "linear", "wrap": "repeat",
                                               "width": 16, "height": 16, "pattern": "noise", "seed": seed}, **k)
for pair in [["one", "one"], ["src_alpha", "one"], ["one", "one_minus_src_alpha"], ["dst_colour", "zero"],
             ["one_minus_dst_alpha", "one"], ["src_colour", "one_minus_src_colour"], ["one", "zero", "zero", "one"],
             ["zero", "src_alpha", "one", "one"]]:
    write("blend-" + "-".join(p.replace("_", "-") for p in pair), {"kind": "conformance",
      "description": f"Three overlapping textured triangles blended with glBlendFuncSeparate({', '.join(pair)}) over a non-zero clear colour.",
      "width": 64, "height": 64, "fragment": "sample_implicit", "clear_colour": [0.2, 0.35, 0.5, 0.75],
      "blend": pair, "textures": [noise(41)], "triangles": overlapping()})

for fmt in ["rgba16f", "rgba32f"]:
    write(f"two-pass-{fmt}", {"kind": "conformance",
      "description": f"Render to texture: a {fmt} 32x32 target drawn (additively, two overlapping triangles, values past 1) then sampled magnified with a linear filter in the scene's pass.",
      "width": 64, "height": 64,
      "targets": [{"name": "lit", "width": 32, "height": 32, "format": fmt}],
      "passes": [{"target": "lit", "fragment": "sample_implicit", "clear_colour": [0.1, 0.2, 0.3, 1.0],
                  "blend": ["one", "one"], "textures": [noise(42)],
                  "triangles": [{"positions": [[1, 1], [31, 3], [4, 30]], "uvs": [[0, 0], [2.3, 0.1], [0.2, 1.9]],
                                 "colours": [[3.1, 0.7, 0.2, 1], [0.3, 2.2, 0.9, 1], [0.1, 0.5, 70000.0, 1]]},
                                {"positions": [[30, 30], [2, 28], [29, 2]], "uvs": [[1, 1], [0, 0.9], [0.8, 0]],
                                 "colours": [[1, 1, 1, 1], [0.25, 0.5, 1, 1], [1, 0.001, 0.3, 1]]}]}],
      "fragment": "sample_implicit",
      "textures": [{"sampler": "tex", "target": "lit", "filter": "linear", "wrap": "clamp"}],
      "triangles": quad(0.5, 0.5, 63.5, 63.5, -0.1, -0.1, 1.1, 1.1, skew=1.0)})

write("bloom-chain", {"kind": "conformance",
  "description": "An HDR bloom chain: a bright pass into an RGBA16F target, a half-size blur of it into level 1 of a second target through a viewport, then the scene's pass adds the blurred level over the sharp image with (one, one).",
  "width": 64, "height": 64,
  "targets": [{"name": "bright", "width": 32, "height": 32, "format": "rgba16f"},
              {"name": "blur", "width": 32, "height": 32, "format": "rgba16f", "levels": 2}],
  "passes": [{"target": "bright", "fragment": "sample_implicit", "textures": [noise(43)],
              "triangles": quad(0, 0, 32, 32, 0, 0, 2, 2, cols=[[4, 2, 1, 1], [1, 4, 2, 1], [2, 1, 4, 1], [3, 3, 3, 1]], skew=0.0)},
             {"target": "blur", "level": 1, "viewport": [2, 1, 13, 14], "fragment": "sample_lod",
              "uniforms": [{"name": "lod_min", "float": 0.0}, {"name": "lod_max", "float": 0.0}],
              "textures": [{"sampler": "tex", "target": "bright", "filter": "linear", "wrap": "clamp"}],
              "triangles": quad(0, 0, 16, 16, 0.02, 0.03, 0.98, 0.97, skew=0.0)},
             {"target": "blur", "level": 0, "clear": False, "viewport": [5, 7, 20, 17], "fragment": "sample_implicit",
              "textures": [{"sampler": "tex", "target": "bright", "filter": "nearest", "wrap": "repeat"}],
              "triangles": quad(0, 0, 32, 32, 0.5, 0.5, 1.5, 1.5, skew=2.0)}],
  "fragment": "sample_implicit", "blend": ["one", "one"],
  "textures": [{"sampler": "tex", "target": "blur", "min_filter": "linear_mipmap_linear", "mag_filter": "linear", "wrap": "clamp"}],
  "triangles": quad(0.5, 0.5, 63.5, 63.5, 0.0, 0.0, 1.0, 1.0, skew=1.5)})

# The search loop of loop-exit on a mip chain: implicit LOD inside a loop
# whose lanes leave at different passes (exited neighbours keep their
# coordinates while the quad's LOD is taken).
write("loop-exit-mip", {"kind": "conformance",
  "description": "The search loop of loop-exit sampling a 32x32 rgba8 mip chain (linear_mipmap_linear) with implicit LOD inside the loop, lanes leaving at different passes.",
  "width": 64, "height": 64, "fragment": "loop_exit",
  "uniforms": [{"name": "steps", "int": 24}, {"name": "dir", "vec2": [0.031, 0.047]}, {"name": "threshold", "float": 0.8}],
  "textures": [{"sampler": "tex", "format": "rgba8", "min_filter": "linear_mipmap_linear", "mag_filter": "linear",
                "wrap": "repeat", "width": 32, "height": 32, "pattern": "noise", "seed": 51, "mipmaps": "distinct"}],
  "triangles": quad(1.5, 2.25, 62.5, 61.75, -0.2, -0.1, 2.3, 2.2)})

# Every filter x wrap x format, magnified and minified (the repeat wrap with
# the four mip filters is above): 12x10 npot box chains for clamp and
# mirrored repeat, 16x16 for repeat's two plain filters.
for fmt in ["rgba8", "rgba32f", "rgba16f", "r32f"]:
    for wrap in ["repeat", "clamp", "mirrored_repeat"]:
        for mf in ["nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest", "nearest_mipmap_linear",
                   "linear_mipmap_linear"]:
            if wrap == "repeat" and "mipmap" in mf:
                continue  # conformance-mip-<format>-<filter>
            if wrap != "repeat" and mf == "linear_mipmap_linear" and fmt in ("rgba8", "rgba32f"):
                continue  # conformance-mip-<format>-wrap-<wrap>
            mag = "linear" if mf.startswith("linear") else "nearest"
            w, h = (16, 16) if wrap == "repeat" else (12, 10)
            tag = f"{fmt}-{wrap.replace('_', '-')}-{mf.replace('_mipmap_', '-mip-').replace('_', '-')}"
            write(f"filter-{tag}", {"kind": "conformance",
              "description": f"texture() on a {fmt} {w}x{h} box chain, min {mf}, mag {mag}, wrap {wrap}: eight strips from magnified 2.5x to minified 17x.",
              "width": 64, "height": 64, "fragment": "sample_implicit",
              "textures": [{"sampler": "tex", "format": fmt, "min_filter": mf, "mag_filter": mag, "wrap": wrap,
                            "width": w, "height": h, "pattern": "noise", "seed": 61, "mipmaps": "box"}],
              "triangles": strips([s * 1.3 for s in scales])})

# A texture() with implicit LOD on each side of a divergent branch, on mip
# chains: the coordinates are computed inside the branch (NIR SSA values),
# so a quad's inactive lanes contribute their own, as the twin computes them.
write("branch-texture-mip", {"kind": "conformance",
  "description": "branch-texture on mip chains: implicit-LOD texture() on both sides of a divergent branch (rgba8 trilinear, rgba32f nearest-mip-nearest), quads split by the branch.",
  "width": 64, "height": 64, "fragment": "branch_texture",
  "uniforms": [{"name": "split", "float": 0.8}],
  "textures": [{"sampler": "tex_a", "format": "rgba8", "min_filter": "linear_mipmap_linear", "mag_filter": "linear",
                "wrap": "repeat", "width": 32, "height": 32, "pattern": "noise", "seed": 71, "mipmaps": "distinct"},
               {"sampler": "tex_b", "format": "rgba32f", "min_filter": "nearest_mipmap_nearest", "mag_filter": "nearest",
                "wrap": "clamp", "width": 24, "height": 20, "pattern": "noise", "seed": 72, "mipmaps": "distinct"}],
  "triangles": quad(2.5, 1.5, 61.5, 62.5, -0.1, -0.1, 3.1, 4.1)})

# Sampler state that shapes the LOD: GL_TEXTURE_LOD_BIAS (quantized to
# 1/256), MIN_LOD/MAX_LOD clamps, MIN_LOD == MAX_LOD (the LOD fixed).
for fmt in ["rgba8", "rgba32f"]:
    for name, state in [("bias", {"lod_bias": 0.3}), ("clamp", {"min_lod": 1.25, "max_lod": 2.5}),
                        ("fixed", {"min_lod": 1.5, "max_lod": 1.5}), ("negative-bias", {"lod_bias": -1.7, "max_lod": 3.0})]:
        for mf in ["linear_mipmap_linear", "nearest_mipmap_nearest"]:
            mag = "linear" if mf.startswith("linear") else "nearest"
            tag = f"{fmt}-{name}-{mf.replace('_mipmap_', '-mip-').replace('_', '-')}"
            tex = dict({"sampler": "tex", "format": fmt, "min_filter": mf, "mag_filter": mag, "wrap": "repeat",
                        "width": 16, "height": 16, "pattern": "noise", "seed": 81, "mipmaps": "distinct"}, **state)
            write(f"lod-state-{tag}", {"kind": "conformance",
              "description": f"texture() with sampler state {state} on a {fmt} 16x16 chain, min {mf}.",
              "width": 64, "height": 64, "fragment": "sample_implicit", "textures": [tex],
              "triangles": strips(scales)})
            write(f"lod-state-lod-{tag}", {"kind": "conformance",
              "description": f"textureLod() from -1.5 to 5.5 with sampler state {state} on a {fmt} 16x16 chain, min {mf}.",
              "width": 64, "height": 64, "fragment": "sample_lod",
              "uniforms": [{"name": "lod_min", "float": -1.5}, {"name": "lod_max", "float": 5.5}],
              "textures": [tex], "triangles": strips([1.0] * 8, lod_cols=True)})

# Cube maps with a bias and with textureGrad.
for fmt in ["rgba8", "rgba32f"]:
    for mf in ["linear_mipmap_linear", "nearest_mipmap_nearest"]:
        mag = "linear" if mf.startswith("linear") else "nearest"
        tag = f"{fmt}-{mf.replace('_mipmap_', '-mip-').replace('_', '-')}"
        env = {"sampler": "env", "cube": True, "format": fmt, "min_filter": mf, "mag_filter": mag, "wrap": "clamp",
               "width": 8, "height": 8, "pattern": "noise", "seed": 91, "mipmaps": "distinct"}
        write(f"cube-bias-{tag}", {"kind": "conformance",
          "description": f"texture() with a per-pixel bias from -1.5 to 2.5 on a seamless {fmt} cube map, min {mf}.",
          "width": 64, "height": 64, "fragment": "sample_cube_bias",
          "uniforms": [{"name": "lod_min", "float": -1.5}, {"name": "lod_max", "float": 2.5}],
          "textures": [env], "triangles": cube_quads(lod_cols=True)})
        write(f"cube-grad-{tag}", {"kind": "conformance",
          "description": f"textureGrad() with per-pixel scaled derivatives on a seamless {fmt} cube map, min {mf}.",
          "width": 64, "height": 64, "fragment": "sample_cube_grad",
          "uniforms": [{"name": "grad_scale", "float": 6.0}],
          "textures": [env], "triangles": cube_quads(lod_cols=True)})

# Interpolation qualifiers (varyings.vert and .frag): 48 triangles of both
# windings over and past a 64x64 target, each corner with its own w (so that
# smooth and noperspective differ) and some pushed through the near or far
# plane, so that clipping makes new vertices and new provoking vertices.
def varyings_triangles(n=48, seed=2027):
    state = [seed]
    def rnd():  # a fixed LCG, so the scenes never depend on Python's random
        state[0] = (state[0] * 1103515245 + 12345) % 2**31
        return state[0] / 2**31
    tris = []
    for t in range(n):
        cx, cy, r = -4 + rnd() * 72, -4 + rnd() * 72, 6 + rnd() * 30
        pos, col, uvs = [], [], []
        for k in range(3):
            pos.append([round(cx + (rnd() - 0.5) * 2 * r, 2), round(cy + (rnd() - 0.5) * 2 * r, 2),
                        round(rnd(), 3)])
            col.append([round(rnd() * 4 - 2, 3), round(rnd() * 4 - 2, 3), round(rnd() * 4 - 2, 3), 3 * t + k])
            push = [0, 0, 0, 2, -2][int(rnd() * 5)]
            uvs.append([round(0.5 + rnd() * 3, 3), push])
        tris.append({"positions": pos, "colours": col, "uvs": uvs})
    return tris
for show, tag, what in [(0, "flat-int", "a flat ivec4 of bit patterns no arithmetic may touch (signalling and quiet NaNs with payloads, infinities, -0, denormals), its bits written out"),
                        (1, "flat-float", "a flat vec4 (NaN payloads, infinities, denormals and ordinary values) written as it arrives"),
                        (2, "noperspective", "a noperspective vec4, linear in window space where the corners' w differ"),
                        (3, "smooth", "a smooth (perspective-correct) vec4 beside the other qualifiers"),
                        (4, "mixed", "smooth x, noperspective y, a flat int after an integer add and a flat uint's bits in one pixel")]:
    write(f"varyings-{tag}", {"kind": "conformance",
      "description": f"Interpolation qualifiers through clipping (varyings.vert and .frag, show {show}): {what}; 48 triangles of both windings, each corner with its own w, some past the sides and through the near and far planes, so that the clipper makes new vertices and the provoking (last) vertex moves.",
      "width": 64, "height": 64, "vertex": "varyings", "fragment": "varyings",
      "uniforms": [{"name": "reach", "float": 1.25}, {"name": "show", "int": show}],
      "criteria": {"nonfinite": "identical", "rationale": "Flat inputs are the provoking vertex's bits, NaN payloads and denormals included; smooth and noperspective ones follow llvmpipe's clipper and planes operation for operation: every bit must match."},
      "triangles": varyings_triangles()})
# The parallax benchmark (issue 30): a user's shader on the general sampler
# path at 800x600, the maps from make-bricks-maps.py. A colour is the vector
# to the eye at that corner in tangent space (affine over a plane, so
# interpolating it is exact); the uv covers the bricks twice across, 1.28
# texels a pixel (trilinear between levels 0 and 1).
def parallax(name, desc, height_scale, view):
    W, H = 800, 600
    corners = [(0, 0), (W, 0), (W, H), (0, H)]
    uv = {c: [2.0 * c[0] / W, 1.5 * c[1] / H] for c in corners}
    eye = {c: view(c[0] / W, c[1] / H) + [1] for c in corners}
    tri = lambda a, b, c: {"positions": [list(a), list(b), list(c)], "colours": [eye[a], eye[b], eye[c]],
                           "uvs": [uv[a], uv[b], uv[c]]}
    maps = [dict(sampler=s, pattern="file", file="textures/" + f, format="rgba8", colour_space="linear",
                min_filter="linear_mipmap_linear", mag_filter="linear", wrap="repeat", mipmaps="box")
            for s, f in (("depth_map", "bricks-512-depth.png"), ("colour_map", "bricks-512-colour.png"))]
    write(f"parallax-{name}", {"kind": "conformance", "description": desc, "width": W, "height": H,
      "fragment": "parallax_loop",
      "uniforms": [{"name": "height_scale", "float": height_scale}, {"name": "light_dir", "vec3": [0.48, 0.6, 0.64]}],
      "textures": maps,
      "triangles": [tri(corners[0], corners[1], corners[2]), tri(corners[0], corners[2], corners[3])],
      "criteria": {"rationale": "A benchmark of the general sampler path (issue 30) and a conformance scene: every bit must match."}})
parallax("head-on", "Parallax occlusion mapping as tutorials write it (implicit-LOD texture() in a while loop each lane leaves at its own step, trilinear RGBA8 bricks), 800x600, the eye above the middle: 8 to 11 layers. The benchmark of a user's shader (issue 30).",
         0.05, lambda x, y: [round(0.5 - x, 4), round(0.5 - y, 4), 1.2])
parallax("grazing", "Parallax occlusion mapping as head-on, the eye far to the left and low: the ray 64 to 74 degrees from the normal, 27 to 30 layers of 2 to 3 texels.",
         0.05, lambda x, y: [round(-2.0 - x, 4), round(0.5 - y, 4), 1.0])
parallax("deep", "Parallax occlusion mapping as head-on with twice the depth (0.1 of the map's width) at 45 degrees: long marches into the joints.",
         0.1, lambda x, y: [round(-1.0 - 0.5 * x, 4), round(0.5 - y, 4), 1.3])
