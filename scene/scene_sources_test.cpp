// scene_sources_test.cpp: a user technique's scenes join the built-in ones
// with their own golden file; a name in two places is refused.
#include "scene/scene_sources.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "scene/input_error.h"

namespace st {
namespace {

namespace fs = std::filesystem;

TEST(SceneSources, AUserSourceKeepsItsGoldenFileAndNamesAreUnique) {
    const fs::path dir = fs::temp_directory_path() / ("scene_sources_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    SceneSources sources;
    const auto builtin = sources.entries();
    ASSERT_FALSE(builtin.empty());
    const std::string builtin_golden = builtin.front().golden_file;
    std::ofstream(dir / "user-scene.json") << builtin.front().name;  // content is not read here

    sources.add({"user", {(dir / "user-scene.json").string()}, (dir / "golden.json").string()});
    const auto entry = sources.find("user-scene");
    ASSERT_TRUE(entry.has_value());
    EXPECT_EQ(entry->golden_file, (dir / "golden.json").string());
    EXPECT_EQ(entry->technique, "user");
    EXPECT_EQ(sources.find(builtin.front().name)->golden_file, builtin_golden);
    EXPECT_EQ(sources.default_golden_file(), (dir / "golden.json").string());

    // A built-in name in a user's folder: listing refuses it, naming both files.
    std::ofstream(dir / (builtin.front().name + ".json")) << "{}";
    sources.add({"clash", {dir.string()}, (dir / "golden2.json").string()});
    try {
        sources.entries();
        FAIL() << "a scene name in two places was taken";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("is in two places"), std::string::npos) << e.what();
    }
    EXPECT_THROW(sources.add({"missing", {(dir / "nope.json").string()}, ""}), InputError);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace st
