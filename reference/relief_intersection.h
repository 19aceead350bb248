// relief_intersection.h: the exact first intersection of a relief-mapping
// view ray with a height field, in double precision: the ground truth that a
// shader's linear / binary / secant search (Timonen's relief mapping,
// ../shared/papers/004_e2e5a695662ff61c.txt Sec. 3) is judged against. Used
// only to measure that search's error, never to render.
//
// The height field is the alpha channel of an RGBA8 texture (alpha / 255,
// exact k/255 in double) with REPEAT wrap, filtered as GL does in exact
// arithmetic: bilinear within a level (x = u*w - 0.5, y = v*h - 0.5), and
// two levels blended trilinearly as (1 - f) * h_L0 + f * h_L1.
//
// The ray enters at (u0, v0) at height 1 and reaches (u0 + du, v0 + dv) at
// height 0; at t in [0, 1] it is at (u0 + t du, v0 + t dv), height 1 - t.
// Its first crossing is the smallest t with 1 - t <= H(t). [0, 1] is split
// wherever either level's x or y crosses an integer; inside each piece the
// texel cells are fixed and g(t) = (1 - t) - H(t) is a polynomial of degree
// <= 2, whose smallest root is solved in closed form. No sampling: the
// answer is exact up to double rounding.
#pragma once

#include <stdexcept>
#include <vector>

#include "frame/frame.h"

namespace st::reference {

// What the exact crossings throw for a ray too long to trace (too many
// texel edges or staircase steps: a view along the surface), apart from
// bad input: a caller may treat such a ray as meeting nothing.
class RayTooLong : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

class ReliefHeightField {
public:
    // Copies the alpha channel of every level. Throws std::invalid_argument
    // unless the texture is a 2D RGBA8 texture with host texels (not a cube
    // map or a render target), REPEAT in both axes, and consistent level sizes.
    explicit ReliefHeightField(const Texture& t);

    int levels() const { return int(levels_.size()); }
    int level_width(int level) const { check_level(level); return levels_[size_t(level)].width; }
    int level_height(int level) const { check_level(level); return levels_[size_t(level)].height; }
    // The stored height of texel (x, y) of a level, alpha / 255, wrapped (REPEAT).
    double texel(int level, int x, int y) const;

    // Bilinear height of one level at (u, v), any finite u, v (REPEAT).
    // Throws std::invalid_argument for a bad level or non-finite u, v.
    double height(int level, double u, double v) const;
    // (1 - f) * height(level0) + f * height(level1), f in [0, 1]; one level
    // only when f == 0 or level0 == level1.
    double height(int level0, int level1, double f, double u, double v) const;

    struct Crossing {
        double t;       // ray parameter in [0, 1]
        double u, v;    // u0 + t du, v0 + t dv (not wrapped)
        double height;  // the blended field there, height(level0, level1, f, u, v)
    };
    // The first crossing of the ray described above with the blended field.
    // Throws std::invalid_argument for non-finite inputs, bad levels or f
    // outside [0, 1], RayTooLong for a ray crossing more than 1e7 texel
    // boundaries.
    Crossing first_crossing(int level0, int level1, double f, double u0, double v0, double du,
                            double dv) const;

private:
    struct Level {
        int width = 0, height = 0;
        std::vector<double> h;  // row-major, alpha / 255
        double at(int x, int y) const { return h[size_t(y) * size_t(width) + size_t(x)]; }
    };
    std::vector<Level> levels_;

    void check_level(int level) const;
};

}  // namespace st::reference
