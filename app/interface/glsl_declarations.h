// glsl_declarations.h: what one GLSL stage declares at global scope, read
// from its source: inputs and outputs with their locations, interface
// blocks, uniforms of every type (samplers, matrices, arrays, structs),
// constants, and each function with its body as written. Two readers:
// `shadertwin new-technique` writes a twin from it (skeleton_files.h), and
// every run checks a draw's uniforms against it (uniform_interface.h).
//
// It reads declarations, not expressions: comments and preprocessor lines
// are skipped (an object-like #define of a whole number is kept, for array
// sizes), and a function body is kept as text. GLSL it cannot place (a
// declaration it does not understand) is refused with the file, the line
// and what it saw, never guessed at.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace st {

struct GlslVariable {
    std::string type;        // "vec3", "mat4", "sampler2D", or a struct's name
    std::string name;
    int array_size = 0;      // 0: not an array
    int location = -1;       // layout(location = N); -1 when not given
    std::vector<std::string> qualifiers;  // flat, noperspective, highp, ...
    std::string initialiser;  // a constant's, as written
    int line = 0;
    // The name GL gives it where that is not `name`: a uniform block with an
    // instance name is the variable `instance` of the block's type, whose
    // members GL names "Block.member" (skeleton_files.cpp).
    std::string gl_name;
    const std::string& gl() const { return gl_name.empty() ? name : gl_name; }
};

struct GlslStruct {
    std::string name;
    std::vector<GlslVariable> members;
};

// `in Block { ... } instance;` and the like. Its members are the stage's
// inputs (outputs, uniforms) named instance.member (or member when there
// is no instance name), as GL names them.
struct GlslBlock {
    std::string storage;  // in, out, uniform, buffer
    std::string name;     // the block's name
    std::string instance; // may be empty
    int array_size = 0;
    int location = -1;
    std::vector<GlslVariable> members;
    int line = 0;
};

struct GlslFunction {
    std::string return_type, name;
    std::string parameters;  // as written, between the parentheses
    std::string body;        // as written, braces included
    int line = 0;
};

struct GlslStage {
    std::string path;
    std::string version;  // "450 core"
    std::vector<GlslVariable> inputs, outputs, uniforms, constants, globals;
    std::vector<GlslStruct> structs;
    std::vector<GlslBlock> blocks;
    std::vector<GlslFunction> functions;  // in source order, main among them
    std::map<std::string, int> defines;   // object-like #defines of whole numbers

    const GlslFunction* function(const std::string& name) const;
    std::string file_name() const;  // the path's last part, for messages
    const GlslStruct* struct_named(const std::string& name) const;
};

// "a vec3", "an int", "a uint": a GLSL type with its article, for messages.
inline std::string with_article(const std::string& type) {
    const char c = type.empty() ? 'x' : type[0];
    return (c == 'a' || c == 'e' || c == 'i' || c == 'o' ? "an " : "a ") + type;
}

// Throws InputError: "PATH:LINE: what is wrong" (a file it cannot read:
// "cannot read PATH").
GlslStage parse_glsl_stage(const std::string& source, const std::string& path);
GlslStage read_glsl_stage(const std::string& path);

}  // namespace st
