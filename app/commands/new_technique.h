// new_technique.h: `shadertwin new-technique NAME VERT FRAG [--out DIR]`:
// a project folder for a shader pair nobody here wrote, with its twins
// written up to their bodies (app/new_technique/skeleton_files.h), which
// builds against the installed package at once and whose `compare` fails,
// saying what is left to write, until the bodies are written.
#pragma once

#include <string>

namespace st {

// Exit 0 with the project written; 2 (one line on stderr, nothing written)
// for a bad name, an unreadable or unsupported shader, or an out folder
// that exists and is not empty.
int cmd_new_technique(const std::string& name, const std::string& vert, const std::string& frag, std::string out_dir);

}  // namespace st
