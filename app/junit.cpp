// junit.cpp: see junit.h. The schema is the common subset that Jenkins,
// GitLab and GitHub's test reporters read: testsuites > testsuite >
// testcase (classname, name, time) > failure (message, body).
#include "app/junit.h"

#include <filesystem>
#include <iomanip>
#include <sstream>

#include "image/image_io.h"
#include "scene/input_error.h"

namespace st {

namespace fs = std::filesystem;

namespace {

// Length of the valid UTF-8 sequence at s[i], or 0.
size_t utf8_length(const std::string& s, size_t i) {
    const auto byte = [&](size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
    const unsigned c = byte(i);
    const auto cont = [&](size_t k) { return (byte(k) & 0xC0u) == 0x80u; };
    if (c < 0x80) return 1;
    if (c >= 0xC2 && c <= 0xDF) return cont(i + 1) ? 2 : 0;
    if (c >= 0xE0 && c <= 0xEF) {
        const unsigned c1 = byte(i + 1);
        if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 > 0x9F)) return 0;  // overlong, surrogates
        return cont(i + 1) && cont(i + 2) ? 3 : 0;
    }
    if (c >= 0xF0 && c <= 0xF4) {
        const unsigned c1 = byte(i + 1);
        if ((c == 0xF0 && c1 < 0x90) || (c == 0xF4 && c1 > 0x8F)) return 0;
        return cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    }
    return 0;
}

std::string xml_text(const std::string& in) {
    static const std::string kReplacement = "\xEF\xBF\xBD";
    std::string out;
    for (size_t i = 0; i < in.size();) {
        const size_t n = utf8_length(in, i);
        if (n == 0) {
            out += kReplacement;
            ++i;
            continue;
        }
        const unsigned char c = static_cast<unsigned char>(in[i]);
        if (n == 1) {
            switch (c) {
                case '&': out += "&amp;"; break;
                case '<': out += "&lt;"; break;
                case '>': out += "&gt;"; break;
                case '"': out += "&quot;"; break;
                case '\'': out += "&apos;"; break;
                case '\t': case '\n': case '\r': out += char(c); break;
                default: out += c < 0x20 || c == 0x7F ? kReplacement : std::string(1, char(c));
            }
        } else {
            out.append(in, i, n);
        }
        i += n;
    }
    return out;
}

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
      << "<testsuites name=\"" << xml_text(suite_) << "\"" << counts << ">\n"
      << "  <testsuite name=\"" << xml_text(suite_) << "\"" << counts << ">\n";
    for (const JunitCase& c : cases_) {
        x << "    <testcase classname=\"" << xml_text(c.classname) << "\" name=\"" << xml_text(c.name)
          << "\" time=\"" << seconds(c.seconds) << "\"";
        if (c.failures.empty()) {
            x << "/>\n";
            continue;
        }
        x << ">\n      <failure message=\"" << xml_text(joined(c.failures)) << "\">" << xml_text(c.detail)
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
