// file_provenance_test.cpp: each text format records the line in its own
// syntax, where that syntax allows it, and the record reads back.
#include "image/file_provenance.h"

#include <gtest/gtest.h>

namespace st {

TEST(FileProvenance, EachTextFormatRecordsTheLineInItsSyntax) {
    const std::string line = "shadertwin 0.1.0 (abc), GCC 12; CPU flags avx2";
    EXPECT_EQ(with_provenance("t.csv", "a,b\n1,2\n", line), "# made by: " + line + "\na,b\n1,2\n");
    EXPECT_EQ(with_provenance("t.svg", "<svg/>\n", line), "<!-- made by: " + line + " -->\n<svg/>\n");
    EXPECT_EQ(with_provenance("t.md", "# Title\n", line), "<!-- made by: " + line + " -->\n# Title\n");
    // A declaration or doctype must stay first.
    EXPECT_EQ(with_provenance("t.xml", "<?xml version=\"1.0\"?>\n<a/>\n", line),
              "<?xml version=\"1.0\"?>\n<!-- made by: " + line + " -->\n<a/>\n");
    EXPECT_EQ(with_provenance("t.html", "<!doctype html>\n<html></html>\n", line),
              "<!doctype html>\n<!-- made by: " + line + " -->\n<html></html>\n");
    // JSON has no comments; other files are not ours to change.
    EXPECT_EQ(with_provenance("hashes.json", "{}\n", line), "{}\n");
    EXPECT_EQ(with_provenance("notes.txt", "x", line), "x");
    EXPECT_EQ(with_provenance("t.csv", "a\n", ""), "a\n");
}

TEST(FileProvenance, TheRecordReadsBack) {
    const std::string line = "shadertwin 0.1.0 (abc); CPU flags avx2";
    EXPECT_EQ(recorded_provenance(with_provenance("t.svg", "<svg/>\n", line)), line);
    EXPECT_EQ(recorded_provenance(with_provenance("t.csv", "a\n", line)), line);
    EXPECT_EQ(recorded_provenance("<svg/>\n"), "");
    // A copy's record comes first; the maker's is the one read.
    const std::string made = with_provenance("t.svg", "<svg/>\n", line);
    const std::string copied = with_provenance("t.svg", made, "shadertwin 0.2.0 (def)", "copied by");
    EXPECT_EQ(copied.rfind("<!-- copied by: shadertwin 0.2.0 (def) -->\n", 0), 0u) << copied;
    EXPECT_EQ(recorded_provenance(copied), line);
}

TEST(FileProvenance, TheLineCannotBreakOutOfAComment) {
    FileProvenance p;
    p.line = "a -- b\nc-->d";
    set_file_provenance(p);
    const std::string stored = file_provenance().line;
    EXPECT_EQ(stored.find("--"), std::string::npos) << stored;
    EXPECT_EQ(stored.find('\n'), std::string::npos) << stored;
    set_file_provenance({});
}

}  // namespace st
