// paper_timing_test.cpp: a scene's "paper" field, read strictly.
#include "scene/paper_timing.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"

namespace st {

namespace {

std::optional<PaperTiming> read(const char* text) {
    const nlohmann::json scene = nlohmann::json::parse(text);
    JsonReader r(scene, "");
    auto t = PaperTiming::read(r);
    r.finish();
    return t;
}

}  // namespace

TEST(PaperTiming, ReadsTheRowAndIsOptional) {
    const auto t = read(R"({"paper": {"source": "Timonen, Table 1", "row": "Relief mapping",
                                      "hardware": "GeForce 7600GS", "fps": 33.0}})");
    ASSERT_TRUE(t);
    EXPECT_EQ(t->row, "Relief mapping");
    EXPECT_EQ(t->hardware, "GeForce 7600GS");
    EXPECT_EQ(t->fps, 33.0);
    EXPECT_FALSE(read("{}"));
}

TEST(PaperTiming, RefusesMissingMistypedAndOutOfRangeFields) {
    EXPECT_THROW(read(R"({"paper": {"source": "s", "row": "r", "hardware": "h"}})"), InputError);
    EXPECT_THROW(read(R"({"paper": {"source": "s", "row": "r", "hardware": "h", "fps": 0}})"), InputError);
    EXPECT_THROW(read(R"({"paper": {"source": "s", "row": "r", "hardware": "h", "fps": -3}})"), InputError);
    EXPECT_THROW(read(R"({"paper": {"source": "s", "row": "r", "hardware": "h", "fps": "33"}})"), InputError);
    EXPECT_THROW(read(R"({"paper": {"source": "", "row": "r", "hardware": "h", "fps": 1}})"), InputError);
    EXPECT_THROW(read(R"({"paper": {"source": "s", "row": "r", "hardware": "h", "fps": 1, "year": 2006}})"),
                 InputError);
    EXPECT_THROW(read(R"({"paper": 33})"), InputError);
}

}  // namespace st
