// output_provenance.h: what the tool records in every file it writes
// (image/file_provenance.h): shadertwin's version and commit, the compiler
// and lane width it was built with, the CPU's flags, and, once the GL
// reference has run in this process, Mesa's version, the renderer and the GL
// platform.
#pragma once

#include <string>

namespace st {

// The commit the tool was built from (git describe; "unknown" outside git).
const char* shadertwin_git_commit();

// Sets the record from what the build knows; the tool calls it at start.
void record_build_provenance();
// Adds the GL reference to the record; called when a GL context is made.
void record_gl_provenance(const std::string& gl_renderer, const std::string& gl_version,
                          const std::string& gl_platform);

// The record's one line, as text files carry it.
std::string provenance_line();

}  // namespace st
