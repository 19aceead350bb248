// uniform_interface.h: a draw's uniforms and textures checked against what
// its program's GLSL declares, before anything renders (issue 29), so that a
// gap between a scene, its shader and its twin is one line naming it rather
// than wrong pixels: GL reads a uniform nobody set as 0, skips one the
// program does not have, and sets nothing at all for a value of another type
// (glUniform* fails), while the twin reads whatever the scene gave it.
//
// Refused, each with one line naming the uniform and both sides' view:
// - a uniform the draw sets that neither stage declares (a typo, or an array
//   index or struct member the declaration does not have), unless its name
//   begins with `twin_` (a switch only the twin reads). Read from the
//   declarations, not from GL's active list, so that a uniform the compiler
//   optimised away is told apart from one nobody declared;
// - a value of another type than the declaration's (a mat4 for a mat3; bool
//   and bvecN are set as int and ivecN, as glUniform*i sets them), or a
//   value for a sampler;
// - a uniform set twice in one draw;
// - a texture bound to a sampler name the stages do not declare, or a 2D
//   texture on a samplerCube (and the reverse);
// - where the run has GL: a uniform active in the linked program (GL's
//   reflection) that the draw never sets, each element of an array and each
//   member of a struct or block; GL would read 0 where the twin reads what
//   the scene gave it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/interface/glsl_declarations.h"
#include "frame/frame.h"
#include "gl/gl_renderer.h"

namespace st {

using ActiveUniforms = std::vector<GlRenderer::ActiveUniform>;

// Throws InputError with one line for the first problem of `draw` against
// its vertex and fragment stages and, when not null, the program's active
// uniforms.
void check_draw_uniforms(const DrawCall& draw, const GlslStage& vertex, const GlslStage& fragment,
                         const ActiveUniforms* active);

// The same for every draw of `frame`, the stages read (once per file, with
// `#include` spliced) from `glsl_roots` as the GL side finds them, and each
// program's active uniforms from `active` (once per program; empty: the run
// has no GL, and that check is skipped).
using ActiveUniformsOf = std::function<ActiveUniforms(const std::string& vertex, const std::string& fragment)>;
void check_frame_uniforms(const Frame& frame, const std::vector<std::string>& glsl_roots, const ActiveUniformsOf& active);

// Makes check_frame_uniforms part of loading every scene (scene.h's
// set_frame_check), with the tool's GLSL roots and, for the active uniforms,
// a GL context of its own on `platform`, made at the first scene (none when
// the platform has no GL: that check is then skipped).
void install_frame_check(GlPlatform platform);

}  // namespace st
