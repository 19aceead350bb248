// twin_correspondence_test.cpp: every GLSL file has its C++ twin, every
// function of the GLSL has a twin function of the same name, in the same
// order, and every registered twin has its GLSL file.
//
// Naming: glsl/<stem>.vert -> kernels/<stem>_vert.cpp, glsl/<stem>.frag ->
// kernels/<stem>_frag.cpp, glsl/<stem>.glsl (included model code) ->
// kernels/<stem>.cpp. A shader's main() is the twin's run() (vertex) or
// main() (fragment).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "kernels/registry.h"

namespace st {

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Names of the functions a file defines, in order. GLSL and C++ definitions
// both start a line with a return type, then the name and '('.
std::vector<std::string> defined_functions(const std::string& source, bool cpp) {
    static const std::regex glsl_def(
        R"(^(?:float|int|bool|void|vec[234]|ivec[234]|mat[234]|[A-Z]\w*)\s+(\w+)\s*\()");
    static const std::regex cpp_def(
        R"(^(?:float|int|bool|void|glm::vec[234]|glm::ivec[234]|glm::mat[234]|[A-Z]\w*)\s+(?:\w+::)?(\w+)\s*\()");
    std::vector<std::string> names;
    std::istringstream lines(source);
    std::string line;
    std::smatch m;
    while (std::getline(lines, line))
        if (std::regex_search(line, m, cpp ? cpp_def : glsl_def)) names.push_back(m[1]);
    return names;
}

fs::path twin_of(const fs::path& glsl) {
    const std::string ext = glsl.extension().string();
    const std::string stem = glsl.stem().string();
    const std::string name = ext == ".glsl" ? stem : stem + "_" + ext.substr(1);
    return fs::path(SHADERTWIN_SOURCE_DIR) / "kernels" / (name + ".cpp");
}

std::vector<fs::path> glsl_files() {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(fs::path(SHADERTWIN_SOURCE_DIR) / "glsl")) {
        const auto ext = e.path().extension();
        if (ext == ".vert" || ext == ".frag" || ext == ".glsl") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST(Twins, EveryShaderFunctionHasItsTwinInOrder) {
    const auto files = glsl_files();
    ASSERT_GT(files.size(), 10u);
    for (const fs::path& glsl : files) {
        const fs::path twin = twin_of(glsl);
        ASSERT_TRUE(fs::exists(twin)) << glsl.filename() << " has no twin " << twin.filename();
        std::vector<std::string> expected = defined_functions(read(glsl), false);
        std::vector<std::string> actual = defined_functions(read(twin), true);
        // main() is run() in a vertex twin.
        for (auto& name : expected)
            if (name == "main" && glsl.extension() == ".vert") name = "run";
        // The twin may define helpers of its own (bind, ...): compare the
        // shader's functions as a subsequence, in order.
        std::vector<std::string> matched;
        size_t next = 0;
        for (const auto& name : actual)
            if (next < expected.size() && name == expected[next]) {
                matched.push_back(name);
                ++next;
            }
        EXPECT_EQ(matched, expected) << twin.filename() << " does not mirror " << glsl.filename();
    }
}

TEST(Twins, EveryRegisteredTwinHasItsShader) {
    const fs::path dir = fs::path(SHADERTWIN_SOURCE_DIR) / "glsl";
    for (const auto& name : vertex_twin_names())
        EXPECT_TRUE(fs::exists(dir / (name + ".vert"))) << "vertex twin " << name;
    for (const auto& name : fragment_twin_names())
        EXPECT_TRUE(fs::exists(dir / (name + ".frag"))) << "fragment twin " << name;
}

}  // namespace st
