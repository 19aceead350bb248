// profile_thickness.cpp: the vein thickness map of profile_thickness.h.
#include "scene/profile_thickness.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/input_error.h"

namespace st {

ThicknessMap read_thickness_map(JsonReader& geometry, const ProfileShape& shape) {
    ThicknessMap map;
    auto t = geometry.object_if("thickness_map");
    if (!t) return map;
    if (shape.kind == "ellipsoid" || shape.kind == "mesh")
        throw InputError("field '" + geometry.field("thickness_map") + "': veins are laid out on a slab or a sheet");
    // Domains and defaults: scene/profile_space.cpp.
    map.height_mm = t->number("height_mm");
    map.vein_spacing_mm = t->number("vein_spacing_mm");
    map.vein_width_mm = t->number("vein_width_mm");
    t->finish();
    return map;
}

Texture thickness_texture(const ThicknessMap& map, const ProfileShape& shape, int size) {
    Texture t;
    t.sampler = "thickness_map";
    t.format = TextureFormat::RGBA32F;
    t.set_filter(TextureFilter::Nearest);
    t.set_wrap(TextureWrap::ClampToEdge);
    if (!(map.height_mm > 0)) {
        t.width = t.height = 1;
        t.texels32 = {0.0f, 0.0f, 0.0f, 0.0f};
        return t;
    }
    t.width = t.height = size;
    t.texels32.assign(size_t(size) * size_t(size) * 4, 0.0f);
    const double angle = 40.0 * std::numbers::pi / 180.0;
    const double half = 0.5 * shape.size_mm, w = map.vein_width_mm, spacing = map.vein_spacing_mm;
    auto ridge = [w](double d) { return std::exp(-(d * d) / (w * w)); };
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            // The texel centre on the unbent square, mm.
            const double x = ((i + 0.5) / size * 2.0 - 1.0) * half, y = ((j + 0.5) / size * 2.0 - 1.0) * half;
            const double ax = std::abs(x);
            // Side veins: lines y = |x| tan(angle) + k spacing, rising away from the midrib.
            const double s = (y - ax * std::tan(angle)) / spacing;
            const double d_side = std::abs(s - std::round(s)) * spacing * std::cos(angle);
            const double fade = std::max(0.0, 1.0 - ax / half);  // thinner towards the rim
            const double h = std::max(ridge(ax / 2.0), 0.6 * fade * ridge(d_side));
            t.texels32[(size_t(j) * size_t(size) + size_t(i)) * 4] = float(h);
        }
    }
    return t;
}

}  // namespace st
