// file_provenance.h: every file the tool writes records what made it.
//
// The tool sets the record once it knows it (app/output_provenance.h: the
// versions, the compiler and lane width, the CPU flags, and Mesa's once the
// GL reference has run); the writers of image_io.h put it in each file:
// EXR and PNG as attributes (PNG text chunks), text files as one comment
// line in their own syntax. JSON has no comments and stays as it is: the
// golden file is committed and must not change with the machine.
#pragma once

#include <map>
#include <string>

namespace st {

struct FileProvenance {
    std::map<std::string, std::string> attributes;  // for images: "shadertwin:<key>"
    std::string line;                               // for text files: one line, no "--"
};

void set_file_provenance(FileProvenance provenance);
const FileProvenance& file_provenance();

// `text` with `line` recorded in the syntax of `path`'s extension: a first
// "# made by: ..." line in .csv; a "<!-- made by: ... -->" line in .svg, .md,
// .html and .xml (after an XML declaration or doctype, which must come
// first); any other file unchanged. Nothing is added when `line` is empty.
// `verb` names the act recorded: "made by" for a file the process made,
// "copied by" for one it only copied (whose own record, if any, stays the
// one recorded_provenance reads).
std::string with_provenance(const std::string& path, const std::string& text, const std::string& line,
                            const std::string& verb = "made by");

// The line a stamped text records, or "" when it records none.
std::string recorded_provenance(const std::string& text);

}  // namespace st
