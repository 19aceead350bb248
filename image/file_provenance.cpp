// file_provenance.cpp: see file_provenance.h.
#include "image/file_provenance.h"

#include <filesystem>

namespace st {

namespace {

FileProvenance& current() {
    static FileProvenance p;
    return p;
}

constexpr const char* kMadeBy = "made by: ";

// After a first line that must stay first (an XML declaration or a doctype).
size_t insertion_point(const std::string& text) {
    if (text.rfind("<?xml", 0) == 0 || text.rfind("<!doctype", 0) == 0 || text.rfind("<!DOCTYPE", 0) == 0) {
        const size_t end = text.find('\n');
        return end == std::string::npos ? text.size() : end + 1;
    }
    return 0;
}

}  // namespace

void set_file_provenance(FileProvenance provenance) {
    // A comment may not hold "--" (XML) nor a line break (every syntax here).
    std::string line;
    for (char c : provenance.line) {
        if (c == '\n' || c == '\r') c = ' ';
        if (c == '-' && !line.empty() && line.back() == '-') line += ' ';
        line += c;
    }
    provenance.line = std::move(line);
    current() = std::move(provenance);
}

const FileProvenance& file_provenance() { return current(); }

std::string with_provenance(const std::string& path, const std::string& text, const std::string& line,
                            const std::string& verb) {
    if (line.empty()) return text;
    const std::string ext = std::filesystem::path(path).extension().string();
    const std::string record = verb + ": " + line;
    if (ext == ".csv") return "# " + record + "\n" + text;
    if (ext == ".svg" || ext == ".md" || ext == ".html" || ext == ".xml") {
        std::string out = text;
        const size_t at = insertion_point(text);
        if (at == text.size() && !text.empty() && text.back() != '\n') out += "\n";
        out.insert(at == text.size() ? out.size() : at, "<!-- " + record + " -->\n");
        return out;
    }
    return text;
}

std::string recorded_provenance(const std::string& text) {
    const size_t at = text.find(kMadeBy);
    if (at == std::string::npos || at > 512) return "";
    const size_t start = at + std::string(kMadeBy).size();
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (line.size() >= 4 && line.compare(line.size() - 4, 4, " -->") == 0) line.resize(line.size() - 4);
    return line;
}

}  // namespace st
