// varying_interface.h: a draw's twins checked against its GLSL's inputs and
// outputs before anything renders (issue 29). GL links varyings by name or
// location and never sees the twins; the CPU pipeline hands the vertex
// twin's slot N to the fragment twin's slot N and never sees the GLSL. A
// twin reading slot 2 where the shader declares Normal at 1 would show only
// as wrong pixels; here it is one line.
//
// A twin's slot is mapped to a GLSL variable by its name where the twin
// names its slots (input_names(), output_names(): what `new-technique`
// writes, and what a shader without locations needs), else by the GLSL's
// explicit location. Refused, each with one line naming the variable and
// both sides' view:
// - a slot the twin names that the GLSL does not declare, or declares at
//   another location; the same name at different slots in the two twins;
// - a component the fragment twin reads (inputs_read()) of a slot the GLSL
//   declares nothing at, or past the declared type's size (z of a vec2);
// - an interpolation qualifier (flat, noperspective) other than the twin's
//   interpolations();
// - an input the fragment shader's code uses whose slot the twin's
//   inputs_read() leaves out (it would read NaN), or that the twin cannot
//   place (no location and no name);
// - a slot the fragment twin reads that the vertex twin does not write, and
//   an input the fragment shader uses that no vertex output meets (by
//   location, or by name where either has none), which GL's link refuses;
// - a vertex input at a location past the draw's attributes; where the
//   draw names its attributes (VertexArray::names), a name the vertex
//   shader does not declare as an input, or declares at another location,
//   and an input it uses that no attribute names;
// - fragment outputs other than one per colour buffer of the pass
//   (locations 0 to N-1; with several, each with its location or bound by
//   name, DrawCall::output_names), or a twin
//   writing another number of them (FragmentTwin::output_count()).
// A twin whose inputs_read() is every bit (the default) is not checked for
// what it reads: it has not said.
#pragma once

#include <string>

#include "app/interface/glsl_declarations.h"
#include "shading/program.h"

namespace st {

// Throws InputError with one line for the first mismatch. `vertices` are
// the draw's (their attribute count and names), `targets` the colour
// buffers its pass draws into (1 + Pass::outputs), `output_names` the
// draw's DrawCall::output_names.
void check_twin_varyings(const GlslStage& vertex, const VertexTwin& vertex_twin, const GlslStage& fragment,
                         const FragmentTwin& fragment_twin, const VertexArray& vertices, int targets = 1,
                         const std::vector<std::string>& output_names = {});

}  // namespace st
