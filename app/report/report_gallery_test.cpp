// report_gallery_test.cpp: the report's top (issue 25): a row of
// thumbnails per technique with a failing scene framed, the conformance
// scenes folded unless one fails; and the brief summary ./run.sh prints.
#include "app/report/report_gallery.h"

#include <gtest/gtest.h>

#include <regex>

#include "app/report/report_summary.h"

namespace st {
namespace {

ReportEntry entry(const std::string& scene, const std::string& kind, bool pass, double cpu_ms = 0, double gl_ms = 0) {
    ReportEntry e;
    e.scene = scene;
    e.kind = kind;
    e.comparison.scene = scene;
    e.comparison.metrics.width = 64;
    e.comparison.metrics.height = 32;
    e.comparison.cpu_png = scene + ".cpu.png";
    if (!pass) e.comparison.failures.push_back("max_diff_8bit 9 > 1");
    if (cpu_ms > 0) {
        BenchResult r;
        r.scene = scene;
        r.cpu.ms_median = cpu_ms;
        r.gl.ms_median = gl_ms;
        e.cost = r;
    }
    return e;
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(ReportGallery, OneRowPerTechniqueFailingScenesFramedConformanceFolded) {
    std::vector<ReportEntry> entries = {entry("relief-b", "relief", false), entry("relief-a", "relief", true),
                                        entry("conformance-x", "conformance", true), entry("tri", "triangles", true)};
    entries[1].paper = PaperTiming{"Timonen 2006, Table 1", "Relief mapping", "GeForce 7600GS", 33};
    const std::string g = report_gallery(entries);
    // Techniques in the order named, conformance last and folded (closed: all pass).
    const size_t relief = g.find("id=\"g-relief\""), tri = g.find("id=\"g-triangles\""),
                 conf = g.find("<details class=\"gallery-row\" id=\"g-conformance\">");
    ASSERT_NE(relief, std::string::npos);
    ASSERT_NE(tri, std::string::npos);
    ASSERT_NE(conf, std::string::npos) << g;
    EXPECT_LT(relief, tri);
    EXPECT_LT(tri, conf);
    // A thumbnail per scene, linking to its detail, sorted by name; the failing one framed.
    EXPECT_EQ(count(g, "<a class=\"thumb"), 4u);
    EXPECT_LT(g.find("href=\"#s-relief-a\""), g.find("href=\"#s-relief-b\""));
    EXPECT_NE(g.find("<a class=\"thumb failed\" href=\"#s-relief-b\""), std::string::npos);
    EXPECT_EQ(count(g, "thumb failed"), 1u);
    EXPECT_NE(g.find("<img src=\"relief-a.cpu.png\" width=\"96\" height=\"48\""), std::string::npos);
    // The paper's table beside relief's row; triangles says it has none.
    const std::string relief_row = g.substr(relief, tri - relief);
    EXPECT_NE(relief_row.find("<td>Relief mapping</td>"), std::string::npos);
    EXPECT_NE(relief_row.find("1 fail"), std::string::npos);
    EXPECT_NE(g.substr(tri, conf - tri).find("No published frame rate"), std::string::npos);

    // A failing conformance scene opens the fold.
    entries[2].comparison.failures.push_back("coverage");
    EXPECT_NE(report_gallery(entries).find("id=\"g-conformance\" open>"), std::string::npos);
}

TEST(ReportSummary, BriefSaysWhatWasFoundInAFewLines) {
    const std::vector<ReportEntry> entries = {entry("relief-b", "relief", false, 40, 50), entry("relief-a", "relief", true, 10, 20),
                                              entry("tri", "triangles", true, 5, 10)};
    const std::string b = report_brief(entries, "out/report");
    EXPECT_EQ(count(b, "\n"), 6u) << b;
    EXPECT_NE(b.find("report: 3 scenes, 2 pass, 1 fail\n"), std::string::npos) << b;
    EXPECT_TRUE(std::regex_search(b, std::regex("\n  relief +1 pass +1 fail   CPU / llvmpipe 1.25 to 2.00\n"))) << b;
    EXPECT_TRUE(std::regex_search(b, std::regex("\n  triangles +1 pass +0 fail   CPU / llvmpipe 2.00\n"))) << b;
    EXPECT_NE(b.find("slowest against llvmpipe: relief-b, CPU / llvmpipe 1.25 (25.0 against 20.0 fps)\n"), std::string::npos) << b;
    EXPECT_NE(b.find("failing: relief-b\n"), std::string::npos) << b;
    EXPECT_NE(b.find("report: out/report/index.html (tables: out/report/summary.md)\n"), std::string::npos) << b;
    // The full tables keep every scene.
    const std::string md = report_markdown(entries, "llvmpipe", 10);
    EXPECT_NE(md.find("| relief-b | **FAIL** |"), std::string::npos) << md;
    EXPECT_NE(md.find("## Cost"), std::string::npos);
}

}  // namespace
}  // namespace st
