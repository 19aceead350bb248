// frame.h: one frame's work, described once and handed to both backends.
//
// A Frame is what a scene turns into before anything is drawn: passes, each
// with a render target and an ordered list of draw calls, and each draw call
// with its program name, vertices, uniforms, textures and fixed-function
// state. The CPU rasterizer (raster/) and the GL host (glsl/) both consume
// exactly this, so geometry, uniforms and draw order cannot drift apart.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

namespace st {

// Vertex attributes are vec4 columns, each bound with glVertexAttribPointer
// (4 floats; missing components are (0,0,0,1)) to GLSL location a, or, when
// `names` is given, to the location GL's reflection gives the vertex input
// names[a]: how a shader without layout(location = N) on its inputs is fed.
// The vertex twin reads column a as attributes[a] either way.
struct VertexArray {
    int attribute_count = 0;
    std::vector<glm::vec4> data;  // vertex-major: data[v * attribute_count + a]
    std::vector<std::string> names;  // empty, or attribute_count GLSL input names ("": none)
    int vertex_count() const {
        return attribute_count ? int(data.size()) / attribute_count : 0;
    }
    const glm::vec4* vertex(int v) const { return &data[size_t(v) * attribute_count]; }
};

// A GLSL uniform's type as glUniform* sets it. bool and bvecN are set as
// Int and IVecN (glUniform*i); an element of an array or a member of a
// struct is its own Uniform, named as GL names it ("lights[2]", "mat.albedo").
// The D types are GLSL's double, dvecN and dmatN (glUniform*d).
enum class UniformType {
    Float, Vec2, Vec3, Vec4, Int, Mat4, IVec2, IVec3, IVec4, UInt, UVec2, UVec3, UVec4, Mat2, Mat3,
    Mat2x3, Mat2x4, Mat3x2, Mat3x4, Mat4x2, Mat4x3,  // matCxR: C columns of R rows
    Double, DVec2, DVec3, DVec4, DMat2, DMat3, DMat4, DMat2x3, DMat2x4, DMat3x2, DMat3x4, DMat4x2, DMat4x3
};

struct Uniform {
    std::string name;
    UniformType type = UniformType::Float;
    // Matrices column-major, as glUniformMatrix*fv; every value as a double,
    // which holds each float, double, int32 and uint32 exactly (a float
    // uniform's value is a float's, rounded once where it was set).
    std::array<double, 16> value{};
};

// An integer uniform's value as the 32 bits glUniform*i and *ui take (its
// two's complement), without undefined behaviour for any double: 0 for a
// value no int32 or uint32 holds (NaN included).
inline uint32_t uniform_integer_bits(double v) {
    if (!(v >= -2147483648.0 && v <= 4294967295.0)) return 0u;
    return uint32_t(int64_t(v));
}

// Whether a uniform of type t holds integers (int, uint, bool and their
// vectors), which glUniform*i and *ui set.
inline bool uniform_type_is_integer(UniformType t) {
    switch (t) {
        case UniformType::Int: case UniformType::IVec2: case UniformType::IVec3: case UniformType::IVec4:
        case UniformType::UInt: case UniformType::UVec2: case UniformType::UVec3: case UniformType::UVec4:
            return true;
        default:
            return false;
    }
}

// Storage formats. Texels are given to both backends as RGBA8 bytes or as
// RGBA floats whatever the format; R32F keeps red, RGBA16F stores halves,
// and both backends convert the same way (texture/texel_formats.h).
// SRGB8_ALPHA8 holds sRGB-encoded bytes, which the sampler decodes per
// texel before filtering, as llvmpipe does (texture/srgb_decode.h).
enum class TextureFormat { RGBA8, R32F, RGBA16F, RGBA32F, SRGB8_ALPHA8 };
// Whether the texels are bytes (texels8) rather than floats (texels32).
inline bool holds_bytes(TextureFormat f) { return f == TextureFormat::RGBA8 || f == TextureFormat::SRGB8_ALPHA8; }
enum class TextureFilter { Nearest, Linear };   // filter within a level
enum class MipFilter { None, Nearest, Linear }; // filter between levels
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// One mip level below the base: max(1, width >> L) x max(1, height >> L).
struct TextureLevel {
    int width = 0, height = 0;
    std::vector<uint8_t> texels8;   // RGBA8
    std::vector<float> texels32;    // the float formats, RGBA
};

// A 2D texture or a cube map. Level 0 is width x height with texels8
// (RGBA8: k/255 exactly as uploaded) or texels32 (RGBA floats); `mips`
// holds levels 1..N, generated on the host (texture/mip_generation.h) and
// uploaded level by level, so neither backend depends on glGenerateMipmap.
// A cube map's levels hold its six square faces one after the other, in
// GL's order +X, -X, +Y, -Y, +Z, -Z; it is sampled with seamless filtering.
struct Texture {
    std::string sampler;  // GLSL sampler uniform name
    TextureFormat format = TextureFormat::RGBA32F;
    TextureFilter mag_filter = TextureFilter::Linear;
    TextureFilter min_filter = TextureFilter::Linear;
    MipFilter mip_filter = MipFilter::None;
    TextureWrap wrap_s = TextureWrap::Repeat, wrap_t = TextureWrap::Repeat;
    // GL_TEXTURE_LOD_BIAS, GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD (GL's defaults).
    float lod_bias = 0.0f, min_lod = -1000.0f, max_lod = 1000.0f;
    int width = 0, height = 0;
    std::vector<uint8_t> texels8;   // RGBA8: width*height*4, row 0 = t near 0
    std::vector<float> texels32;    // float formats: width*height*4
    std::vector<TextureLevel> mips;
    bool cube = false;
    // Non-empty: the texture is the named render target as earlier passes
    // of the frame left it (its format, size and levels; the texels above
    // are unused), sampled with the filters and wraps above.
    std::string target;

    int level_count() const { return 1 + int(mips.size()); }
    int faces() const { return cube ? 6 : 1; }
    // One filter for both (the textures of the thin-slab and triangle scenes).
    void set_filter(TextureFilter f) { mag_filter = min_filter = f; }
    void set_wrap(TextureWrap w) { wrap_s = wrap_t = w; }
};

enum class BlendMode {
    None,
    OneSrcAlpha,        // glBlendFunc(GL_ONE, GL_SRC_ALPHA): thin-slab Eq. 9
    SrcAlphaOneMinusSrcAlpha,  // ordinary alpha blending
    Factors,            // DrawState::factors, GL_FUNC_ADD
};

// glBlendFuncSeparate's factors (GL_FUNC_ADD).
enum class BlendFactor {
    Zero, One, SrcColor, OneMinusSrcColor, SrcAlpha, OneMinusSrcAlpha, DstColor, OneMinusDstColor, DstAlpha,
    OneMinusDstAlpha
};
struct BlendFactors {
    BlendFactor src_rgb = BlendFactor::One, dst_rgb = BlendFactor::Zero;
    BlendFactor src_alpha = BlendFactor::One, dst_alpha = BlendFactor::Zero;
};

struct DrawState {
    bool depth_test = false;   // GL_LESS against a 32-bit float depth buffer
    bool depth_write = true;
    BlendMode blend = BlendMode::None;
    BlendFactors factors;      // for BlendMode::Factors
};

// Work the host does on a draw's vertices at the start of every frame, before
// the vertex stage, on both backends (and inside their frame time): the
// thin-slab "CPU" variant evaluates its model per vertex here. run() reads
// some attributes and overwrites others; it must give the same result when
// run again on its own output.
class HostStage {
public:
    virtual ~HostStage() = default;
    virtual void run(VertexArray& vertices) const = 0;
};

struct DrawCall {
    // Program stages by name: glsl/<vertex>.vert and glsl/<fragment>.frag on
    // the GL side, the twins registered under the same names in kernels/.
    std::string vertex;
    std::string fragment;
    VertexArray vertices;
    std::vector<uint32_t> indices;       // triangle list
    std::vector<Uniform> uniforms;
    std::vector<Texture> textures;       // bound to units 0..N-1 in order
    DrawState state;
    std::shared_ptr<const HostStage> host_stage;  // optional
    // For a fragment shader whose several outputs have no layout(location):
    // the output at each location, 0, 1, ..., as an application binds them
    // with glBindFragDataLocation before linking. Empty: the shader's own
    // locations.
    std::vector<std::string> output_names;
};

// A named render target that passes draw into and later passes sample.
enum class TargetFormat { RGBA16F, RGBA32F };
struct RenderTarget {
    std::string name;
    int width = 0, height = 0;
    TargetFormat format = TargetFormat::RGBA32F;
    int levels = 1;                      // level L is max(1, size >> L)
};

// A fragment output at location 1, 2, ... of a pass (several render
// targets, glDrawBuffers): one level of a named target, the pass's size.
struct PassOutput {
    std::string target;
    int level = 0;
    TargetFormat format = TargetFormat::RGBA32F;  // its target's, as Pass::format
};
inline constexpr int kMaxFragmentOutputs = 4;  // locations 0-3

struct Pass {
    // Empty: the frame's image (RGBA32F, width x height). Else one level of
    // a named target, whose size width x height must be.
    std::string target;
    int level = 0;
    int width = 0, height = 0;           // the colour buffer drawn into, + a 32F depth buffer
    TargetFormat format = TargetFormat::RGBA32F;  // the colour buffer's (its target's) format
    // glViewport within it; width 0 means all of it.
    int viewport_x = 0, viewport_y = 0, viewport_width = 0, viewport_height = 0;
    bool clear = true;                   // else the level keeps what earlier passes left
    glm::vec4 clear_colour{0, 0, 0, 0};
    float clear_depth = 1.0f;
    // Locations 1, 2, ... (location 0 is the colour buffer above), each
    // cleared (or kept) and blended as it is, with the depth test's result.
    std::vector<PassOutput> outputs;
    std::vector<DrawCall> draws;
};

struct Frame {
    std::vector<RenderTarget> targets;
    // In order; the frame's image is what the passes without a target drew
    // (the last of them), and each named target is an output too.
    std::vector<Pass> passes;
};

// The coverage pass used by `compare`: every draw keeps its vertex stage but
// gets the constant-colour fragment stage "coverage" (1.0), no depth test and
// additive blending (ONE, ONE), so a pixel holds how many fragments covered
// it: a pixel covered twice on one side and once on the other is a mismatch.
Frame coverage_frame(const Frame& frame);

}  // namespace st
