// skeleton_files.h: the files of a new technique's project, written from
// its two GLSL stages (`shadertwin new-technique NAME VERT FRAG`): the
// shaders, both twins with everything but their bodies (slot constants,
// inputs_read(), bind() of every uniform, members, the GLSL of main() and
// of every other function as comments to write from), a scene kind that
// reads each uniform from the scene file, one scene, and the CMake lines.
// The project builds against an installed shadertwin at once, and
// `compare` fails until the twins are written, saying so (each twin's
// unwritten()).
//
// The mapping it follows is docs/adding-a-technique.md's: vertex input N is
// attribute N of each vertex (so every input needs its location), varying
// N is slot N (a varying without a location takes the next free slot, and
// a fragment input finds its vertex output by location or by name), and
// the fragment stage writes one vec4. Varyings are float, int and uint
// scalars and vectors; a fragment input's flat or noperspective qualifier
// becomes the twin's interpolations(). Anything outside that (an array
// varying, several outputs, a buffer block) is refused with the file, the
// line and what to change.
#pragma once

#include <string>
#include <vector>

#include "app/interface/glsl_declarations.h"

namespace st::skeleton {

struct ProjectFile {
    std::string path;  // relative to the project folder
    std::string text;
};

// `name` is the technique's (a lower-case C identifier): the GLSL files
// become glsl/<name>.vert and .frag, the tool <name>twin, the scene kind
// <name>. The sources are the stages' text, copied as they are.
std::vector<ProjectFile> skeleton_files(const std::string& name, const GlslStage& vert, const std::string& vert_source,
                                        const GlslStage& frag, const std::string& frag_source);

}  // namespace st::skeleton
