// glsl_declarations.cpp: see glsl_declarations.h. A small lexer (comments,
// preprocessor lines, identifiers, numbers, punctuation, each token with
// its line and its place in the source) and a reader of global-scope
// statements: a statement runs to a `;` or a `{` outside parentheses, and
// its shape says what it is (a function has parentheses after its
// layout(), a block has none, a struct starts with `struct`).
#include "app/interface/glsl_declarations.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "scene/input_error.h"

namespace st {

namespace {

struct Token {
    std::string text;
    int line = 0;
    size_t begin = 0, end = 0;  // in the source
};

bool identifier_start(char c) { return std::isalpha((unsigned char)c) || c == '_'; }
bool identifier_char(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

const std::set<std::string>& qualifier_words() {
    static const std::set<std::string> words = {
        "in",       "out",      "inout",     "uniform",   "buffer",   "const",    "flat",   "smooth",
        "noperspective", "centroid", "sample", "patch",   "invariant", "precise", "highp",  "mediump",
        "lowp",     "readonly", "writeonly", "coherent",  "volatile", "restrict", "shared", "attribute",
        "varying"};
    return words;
}

class Reader {
public:
    Reader(const std::string& source, const std::string& path) : src_(source), path_(path) {}

    GlslStage read() {
        stage_.path = path_;
        lex();
        while (i_ < tokens_.size()) statement();
        return stage_;
    }

private:
    [[noreturn]] void refuse(int line, const std::string& why) const {
        throw InputError(path_ + ":" + std::to_string(line) + ": " + why);
    }

    // --- lexing ---------------------------------------------------------
    void lex() {
        int line = 1;
        bool line_start = true;
        for (size_t p = 0; p < src_.size();) {
            const char c = src_[p];
            if (c == '\n') {
                ++line, ++p, line_start = true;
                continue;
            }
            if (std::isspace((unsigned char)c)) {
                ++p;
                continue;
            }
            if (c == '/' && p + 1 < src_.size() && src_[p + 1] == '/') {
                while (p < src_.size() && src_[p] != '\n') ++p;
                continue;
            }
            if (c == '/' && p + 1 < src_.size() && src_[p + 1] == '*') {
                const size_t close = src_.find("*/", p + 2);
                if (close == std::string::npos) refuse(line, "a comment that never ends");
                line += int(std::count(src_.begin() + long(p), src_.begin() + long(close), '\n'));
                p = close + 2;
                continue;
            }
            if (c == '#' && line_start) {
                size_t e = p;
                std::string directive;
                while (e < src_.size() && src_[e] != '\n') {
                    if (src_[e] == '\\' && e + 1 < src_.size() && src_[e + 1] == '\n') {
                        e += 2, ++line;
                        continue;
                    }
                    directive += src_[e++];
                }
                preprocessor(directive, line);
                p = e;
                continue;
            }
            line_start = false;
            Token t;
            t.line = line, t.begin = p;
            if (identifier_start(c)) {
                while (p < src_.size() && identifier_char(src_[p])) ++p;
            } else if (std::isdigit((unsigned char)c) || (c == '.' && p + 1 < src_.size() && std::isdigit((unsigned char)src_[p + 1]))) {
                while (p < src_.size() && (identifier_char(src_[p]) || src_[p] == '.' ||
                                           ((src_[p] == '+' || src_[p] == '-') && (src_[p - 1] == 'e' || src_[p - 1] == 'E'))))
                    ++p;
            } else {
                ++p;
            }
            t.end = p;
            t.text = src_.substr(t.begin, t.end - t.begin);
            tokens_.push_back(std::move(t));
        }
    }

    void preprocessor(const std::string& directive, int line) {
        std::istringstream in(directive.substr(1));
        std::string word;
        in >> word;
        if (word == "version") {
            std::string rest;
            std::getline(in, rest);
            rest.erase(0, rest.find_first_not_of(" \t"));
            stage_.version = rest;
        } else if (word == "define") {
            std::string name, value, more;
            in >> name >> value;
            if (name.find('(') == std::string::npos && whole_number(value) && !(in >> more))
                stage_.defines[name] = std::stoi(value);
        } else if (word == "include") {
            refuse(line, "#include is not GLSL 4.50 core: paste the included file in");
        }
    }

    static bool whole_number(std::string s) {
        if (!s.empty() && (s.back() == 'u' || s.back() == 'U')) s.pop_back();
        return !s.empty() && s.size() < 9 && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit((unsigned char)c); });
    }

    // --- statements -------------------------------------------------------
    const Token& at(size_t k) const {
        if (k >= tokens_.size()) refuse(tokens_.empty() ? 1 : tokens_.back().line, "the file ends inside a statement");
        return tokens_[k];
    }
    std::string text(size_t from, size_t to) const {  // source of tokens [from, to)
        if (from >= to) return "";
        return src_.substr(tokens_[from].begin, tokens_[to - 1].end - tokens_[from].begin);
    }
    // The token after the bracket that opens at `k` and its match closes.
    size_t after_matching(size_t k) const {
        const std::string open = at(k).text;
        const std::string close = open == "(" ? ")" : open == "[" ? "]" : "}";
        int depth = 0;
        for (size_t j = k; j < tokens_.size(); ++j) {
            if (tokens_[j].text == open) ++depth;
            if (tokens_[j].text == close && --depth == 0) return j + 1;
        }
        refuse(at(k).line, "'" + open + "' never closed");
    }

    void statement() {
        const Token& first = at(i_);
        if (first.text == ";") {
            ++i_;
            return;
        }
        if (first.text == "precision") {
            skip_to_semicolon();
            return;
        }
        if (first.text == "struct") {
            struct_definition();
            return;
        }
        // Its extent: to `;` or `{` outside parentheses and brackets.
        size_t end = i_;
        while (true) {
            const std::string& t = at(end).text;
            if (t == "(" || t == "[") {
                end = after_matching(end);
                continue;
            }
            if (t == ";" || t == "{" || t == "}") break;
            ++end;
        }
        if (at(end).text == "}") refuse(at(end).line, "an unmatched '}'");
        const int line = first.line;
        size_t k = i_;
        const std::map<std::string, std::string> layout = read_layout(k);
        const bool has_paren = std::any_of(tokens_.begin() + long(k), tokens_.begin() + long(end),
                                           [](const Token& t) { return t.text == "("; });
        const bool has_equals = std::any_of(tokens_.begin() + long(k), tokens_.begin() + long(end),
                                            [](const Token& t) { return t.text == "="; });
        if (at(end).text == "{") {
            if (has_paren) function(k, end);
            else block(k, end, layout, line);
            return;
        }
        // `;`: a declaration, a prototype, or a bare layout (`layout(early_fragment_tests) in;`).
        if (k == end || (end - k == 1 && qualifier_words().count(at(k).text))) {
        } else if (has_paren && !has_equals) {
            // A prototype: the definition comes later.
        } else {
            declaration(k, end, layout, line);
        }
        i_ = end + 1;
    }

    void skip_to_semicolon() {
        while (at(i_).text != ";") ++i_;
        ++i_;
    }

    std::map<std::string, std::string> read_layout(size_t& k) const {
        std::map<std::string, std::string> out;
        while (at(k).text == "layout") {
            if (at(k + 1).text != "(") refuse(at(k).line, "layout without '('");
            const size_t close = after_matching(k + 1) - 1;
            for (size_t j = k + 2; j < close;) {
                const std::string key = at(j).text;
                std::string value;
                size_t e = j + 1;
                if (at(e).text == "=") {
                    ++e;
                    const size_t v0 = e;
                    while (e < close && at(e).text != ",") ++e;
                    value = text(v0, e);
                }
                out[key] = value;
                j = e < close && at(e).text == "," ? e + 1 : e;
            }
            k = close + 1;
        }
        return out;
    }

    int array_size(size_t open, size_t& next) {
        next = after_matching(open);
        const size_t close = next - 1;
        if (close == open + 1) refuse(at(open).line, "an array without a size: give it one");
        const std::string expr = text(open + 1, close);
        if (whole_number(expr)) return std::stoi(expr);
        if (const auto d = stage_.defines.find(expr); d != stage_.defines.end()) return d->second;
        for (const GlslVariable& c : stage_.constants)
            if (c.name == expr && whole_number(c.initialiser)) return std::stoi(c.initialiser);
        refuse(at(open).line, "array size '" + expr + "' is not a whole number, a #define or a const int");
    }

    // qualifiers type name[N] = init, name2 ...
    std::vector<GlslVariable> variables(size_t k, size_t end, std::vector<std::string>& qualifiers) {
        while (k < end && qualifier_words().count(at(k).text)) qualifiers.push_back(at(k++).text);
        if (k >= end) refuse(at(end).line, "a declaration without a type");
        GlslVariable proto;
        proto.type = at(k++).text;
        proto.line = at(k - 1).line;
        if (!identifier_start(proto.type[0])) refuse(proto.line, "expected a type, saw '" + proto.type + "'");
        int type_array = 0;
        if (k < end && at(k).text == "[") type_array = array_size(k, k);
        std::vector<GlslVariable> out;
        while (k < end) {
            GlslVariable v = proto;
            v.qualifiers = qualifiers;
            v.name = at(k++).text;
            if (!identifier_start(v.name[0])) refuse(v.line, "expected a name, saw '" + v.name + "'");
            v.array_size = type_array;
            if (k < end && at(k).text == "[") v.array_size = array_size(k, k);
            if (k < end && at(k).text == "=") {
                const size_t v0 = ++k;
                while (k < end && at(k).text != ",") k = at(k).text == "(" ? after_matching(k) : k + 1;
                v.initialiser = text(v0, k);
            }
            out.push_back(std::move(v));
            if (k < end && at(k).text != ",") refuse(at(k).line, "unexpected '" + at(k).text + "' in a declaration");
            if (k < end) ++k;
        }
        return out;
    }

    static std::string storage_of(const std::vector<std::string>& qualifiers, int line, const Reader& r) {
        for (const std::string& q : qualifiers) {
            if (q == "attribute" || q == "varying")
                r.refuse(line, "'" + q + "' is GLSL 1.x: write in and out (#version 330 or later)");
            if (q == "in" || q == "out" || q == "uniform" || q == "buffer" || q == "const" || q == "shared") return q;
        }
        return "";
    }

    void declaration(size_t k, size_t end, const std::map<std::string, std::string>& layout, int line) {
        std::vector<std::string> qualifiers;
        std::vector<GlslVariable> vars = variables(k, end, qualifiers);
        const std::string storage = storage_of(qualifiers, line, *this);
        int location = -1;
        if (const auto l = layout.find("location"); l != layout.end()) {
            if (!whole_number(l->second)) refuse(line, "location '" + l->second + "' is not a whole number");
            location = std::stoi(l->second);
        }
        for (size_t n = 0; n < vars.size(); ++n) {
            GlslVariable& v = vars[n];
            v.location = location < 0 ? -1 : location + int(n);
            if (storage == "in") stage_.inputs.push_back(v);
            else if (storage == "out") stage_.outputs.push_back(v);
            else if (storage == "uniform") stage_.uniforms.push_back(v);
            else if (storage == "const") stage_.constants.push_back(v);
            else if (storage == "buffer") refuse(line, "a buffer variable: shader storage is not modelled");
            else stage_.globals.push_back(v);
        }
    }

    void block(size_t k, size_t brace, const std::map<std::string, std::string>& layout, int line) {
        GlslBlock b;
        b.line = line;
        std::vector<std::string> qualifiers;
        while (k < brace && qualifier_words().count(at(k).text)) qualifiers.push_back(at(k++).text);
        b.storage = storage_of(qualifiers, line, *this);
        if (b.storage.empty() || k + 1 != brace) refuse(line, "expected a block: in, out or uniform, its name, then '{'");
        b.name = at(k).text;
        if (b.storage == "buffer") refuse(line, "buffer block '" + b.name + "': shader storage is not modelled");
        if (const auto l = layout.find("location"); l != layout.end() && whole_number(l->second)) b.location = std::stoi(l->second);
        const size_t close = after_matching(brace) - 1;
        b.members = members(brace + 1, close);
        size_t e = close + 1;
        if (at(e).text != ";") {
            b.instance = at(e++).text;
            if (at(e).text == "[") b.array_size = array_size(e, e);
        }
        if (at(e).text != ";") refuse(at(e).line, "expected ';' after the block '" + b.name + "'");
        stage_.blocks.push_back(std::move(b));
        i_ = e + 1;
    }

    std::vector<GlslVariable> members(size_t from, size_t to) {
        std::vector<GlslVariable> out;
        for (size_t k = from; k < to;) {
            size_t e = k;
            while (e < to && at(e).text != ";") e = at(e).text == "[" || at(e).text == "(" ? after_matching(e) : e + 1;
            size_t m = k;
            const auto layout = read_layout(m);
            std::vector<std::string> qualifiers;
            for (GlslVariable& v : variables(m, e, qualifiers)) {
                if (const auto l = layout.find("location"); l != layout.end() && whole_number(l->second))
                    v.location = std::stoi(l->second);
                out.push_back(std::move(v));
            }
            k = e + 1;
        }
        return out;
    }

    void struct_definition() {
        const int line = at(i_).line;
        GlslStruct s;
        s.name = at(i_ + 1).text;
        if (at(i_ + 2).text != "{") refuse(line, "expected '{' after struct " + s.name);
        const size_t close = after_matching(i_ + 2) - 1;
        s.members = members(i_ + 3, close);
        stage_.structs.push_back(s);
        size_t e = close + 1;
        if (at(e).text != ";") refuse(at(e).line, "a struct declared with a variable: declare the variable apart");
        i_ = e + 1;
    }

    void function(size_t k, size_t brace) {
        GlslFunction f;
        f.line = at(k).line;
        size_t paren = k;
        while (at(paren).text != "(") ++paren;
        if (paren == k) refuse(f.line, "expected a function's name before '('");
        f.name = at(paren - 1).text;
        f.return_type = text(k, paren - 1);
        const size_t close = after_matching(paren) - 1;
        f.parameters = text(paren + 1, close);
        const size_t end = after_matching(brace);
        f.body = src_.substr(tokens_[brace].begin, tokens_[end - 1].end - tokens_[brace].begin);
        stage_.functions.push_back(std::move(f));
        i_ = end;
    }

    const std::string& src_;
    std::string path_;
    std::vector<Token> tokens_;
    size_t i_ = 0;
    GlslStage stage_;
};

}  // namespace

const GlslFunction* GlslStage::function(const std::string& name) const {
    for (const GlslFunction& f : functions)
        if (f.name == name) return &f;
    return nullptr;
}

std::string GlslStage::file_name() const { return std::filesystem::path(path).filename().string(); }

const GlslStruct* GlslStage::struct_named(const std::string& name) const {
    for (const GlslStruct& s : structs)
        if (s.name == name) return &s;
    return nullptr;
}

GlslStage parse_glsl_stage(const std::string& source, const std::string& path) {
    GlslStage stage = Reader(source, path).read();
    if (!stage.function("main")) throw InputError(path + ": no main()");
    return stage;
}

GlslStage read_glsl_stage(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError("cannot read " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return parse_glsl_stage(text.str(), path);
}

}  // namespace st
