// junit.h: JUnit XML for CI systems (`--junit FILE` on compare, golden check
// and report): one test case per scene and per named output, a failing
// case carrying its failure line and where to look (the heat map).
#pragma once

#include <string>
#include <vector>

namespace st {

struct JunitCase {
    std::string classname;  // "shadertwin.<scene kind>", how CI views group cases
    std::string name;       // the scene, or "<scene>:<output>"
    double seconds = 0;
    std::vector<std::string> failures;  // empty: passed
    std::string detail;                 // the failure's body: the heat map's path, the command to update
};

class JunitReport {
public:
    explicit JunitReport(std::string suite) : suite_(std::move(suite)) {}
    void add(JunitCase c) { cases_.push_back(std::move(c)); }
    // The document: one <testsuite> in <testsuites>, text escaped for XML
    // (bytes that are not UTF-8, and control characters XML cannot hold,
    // become U+FFFD).
    std::string xml() const;

private:
    std::string suite_;
    std::vector<JunitCase> cases_;
};

// Refuses (InputError) a path whose folder does not exist or that is a
// folder, so a command stops before it renders anything.
void check_junit_path(const std::string& path);
// Writes the document whole (a temporary file renamed), or not at all.
void write_junit(const std::string& path, const JunitReport& report);

}  // namespace st
