// junit.cpp: see junit.h. The schema is the common subset that Jenkins,
// GitLab and GitHub's test reporters read: testsuites > testsuite >
// testcase (classname, name, time) > failure (message, body).
#include "app/junit.h"

#include "image/file_provenance.h"

#include <filesystem>
#include <iomanip>
#include <sstream>

#include "app/markup_text.h"
#include "image/image_io.h"
#include "scene/input_error.h"

namespace st {

namespace fs = std::filesystem;

namespace {

std::string seconds(double s) {
    std::ostringstream o;
    o << std::fixed << std::setprecision(3) << s;
    return o.str();
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += (out.empty() ? "" : "; ") + l;
    return out;
}

}  // namespace

std::string JunitReport::xml() const {
    size_t failures = 0;
    double total = 0;
    for (const JunitCase& c : cases_) {
        failures += c.failures.empty() ? 0 : 1;
        total += c.seconds;
    }
    std::ostringstream x;
    const std::string counts = " tests=\"" + std::to_string(cases_.size()) + "\" failures=\"" +
                               std::to_string(failures) + "\" errors=\"0\" time=\"" + seconds(total) + "\"";
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites name=\"" << markup_text(suite_) << "\"" << counts << ">\n"
      << "  <testsuite name=\"" << markup_text(suite_) << "\"" << counts << ">\n";
    // What made the results, where CI reporters show a suite's properties.
    if (const auto& made = file_provenance().attributes; !made.empty()) {
        x << "    <properties>\n";
        for (const auto& [name, value] : made)
            x << "      <property name=\"shadertwin." << markup_text(name) << "\" value=\"" << markup_text(value)
              << "\"/>\n";
        x << "    </properties>\n";
    }
    for (const JunitCase& c : cases_) {
        x << "    <testcase classname=\"" << markup_text(c.classname) << "\" name=\"" << markup_text(c.name)
          << "\" time=\"" << seconds(c.seconds) << "\"";
        if (c.failures.empty()) {
            x << "/>\n";
            continue;
        }
        x << ">\n      <failure message=\"" << markup_text(joined(c.failures)) << "\">" << markup_text(c.detail)
          << "</failure>\n    </testcase>\n";
    }
    x << "  </testsuite>\n</testsuites>\n";
    return x.str();
}

void check_junit_path(const std::string& path) {
    std::error_code ec;
    if (path.empty()) throw InputError("--junit needs a file name");
    if (fs::is_directory(path, ec)) throw InputError("--junit " + path + " is a folder, not a file");
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec))
        throw InputError("--junit " + path + ": no folder " + folder.string());
}

void write_junit(const std::string& path, const JunitReport& report) { write_text_file(path, report.xml()); }

}  // namespace st
