// json_reader_test.cpp: parse_json, the depth-bounded parser every scene,
// layer file and --set value goes through. It must accept and refuse
// exactly what the parse callback it replaced did (cli.bad_input checks the
// messages end to end), and build the same document as nlohmann's parse.
#include "scene/json_reader.h"

#include <gtest/gtest.h>

#include <sstream>

#include "scene/input_error.h"

namespace st {
namespace {

// The former bound, kept here as the reference: nlohmann's parse callback
// sees each event with the depth of the containers around it.
nlohmann::json parse_with_callback(const std::string& text) {
    const nlohmann::json::parser_callback_t bound = [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
        if (depth > kMaxJsonDepth) throw InputError("deep");
        return true;
    };
    return nlohmann::json::parse(text, bound, false);
}

std::string nested(int arrays, const std::string& inner) {
    return std::string(size_t(arrays), '[') + inner + std::string(size_t(arrays), ']');
}

std::string nested_objects(int objects, const std::string& inner) {
    std::string s;
    for (int i = 0; i < objects; ++i) s += "{\"k\":";
    s += inner;
    for (int i = 0; i < objects; ++i) s += "}";
    return s;
}

enum class Outcome { Parsed, Malformed, TooDeep };

template <class Parse> Outcome outcome(Parse parse, const std::string& text, nlohmann::json* out = nullptr) {
    try {
        nlohmann::json j = parse(text);
        if (j.is_discarded()) return Outcome::Malformed;
        if (out) *out = std::move(j);
        return Outcome::Parsed;
    } catch (const InputError&) {
        return Outcome::TooDeep;
    }
}

TEST(ParseJson, AgreesWithTheCallbackBoundAtEveryDepthEdge) {
    std::vector<std::string> cases;
    for (int n : {0, 1, 2, kMaxJsonDepth - 1, kMaxJsonDepth, kMaxJsonDepth + 1, kMaxJsonDepth + 2, 200}) {
        for (const std::string inner : {"", "1", "\"s\"", "null", "true", "{}", "{\"a\":1}", "[]", "[1,2]"}) {
            cases.push_back(nested(n, inner));
            cases.push_back(nested_objects(n, inner.empty() ? "0" : inner));
        }
        // Malformed before the depth is reached, at it, and after it.
        cases.push_back("[" + nested(n, "1") + ",]");
        cases.push_back(nested(n, "1,") + "x");
        cases.push_back(std::string(size_t(n), '['));
        cases.push_back("{\"a\" " + nested(n, "1") + "}");
        cases.push_back(nested(n, "1") + " trailing");
    }
    for (const std::string& text : cases) {
        nlohmann::json ours, theirs;
        const Outcome got = outcome([](const std::string& t) { return parse_json(t, "x"); }, text, &ours);
        const Outcome want = outcome(parse_with_callback, text, &theirs);
        ASSERT_EQ(got, want) << text;
        if (got == Outcome::Parsed) {
            EXPECT_EQ(ours, theirs) << text;
        }
    }
}

TEST(ParseJson, RefusesDeepNestingWithTheNameItWasGiven) {
    try {
        parse_json(nested(kMaxJsonDepth + 1, "1"), "scene file x.json");
        FAIL() << "accepted " << kMaxJsonDepth + 1 << " levels";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), ("scene file x.json: nested deeper than " + std::to_string(kMaxJsonDepth) + " levels").c_str());
    }
}

TEST(ParseJson, StreamAndStringGiveTheSameDocument) {
    const std::string text = R"({"kind": "triangles", "triangles": [{"positions": [[1, 2.5], [3, 4], [5e-3, -6]]}],
                                 "big": 18446744073709551615, "neg": -3, "s": "\u00e9", "b": [true, false, null]})";
    std::istringstream stream(text);
    const nlohmann::json a = parse_json(text, "x"), b = parse_json(stream, "x");
    EXPECT_EQ(a, b);
    EXPECT_EQ(a, nlohmann::json::parse(text));
    EXPECT_TRUE(a["big"].is_number_unsigned());
    EXPECT_TRUE(a["neg"].is_number_integer());
    std::istringstream bad("{\"a\": }");
    EXPECT_TRUE(parse_json(bad, "x").is_discarded());
}

}  // namespace
}  // namespace st
