// twin_correspondence_test.cpp: every GLSL file has its C++ twin, every
// function of the GLSL has a twin function of the same name, in the same
// order, and every registered twin has its GLSL file.
//
// Naming: glsl/<technique>/<stem>.vert -> kernels/<technique>/<stem>_vert.cpp,
// .frag -> <stem>_frag.cpp, .glsl (included model code) -> <stem>.cpp. The
// "Twin:" line of each shader's opening comment names that file. A shader's main() is the twin's run() (vertex) or
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
// both start a line with a return type, then the name and '('; a twin
// written once for float and Float returns F, Vec3Of<F> and the like.
std::vector<std::string> defined_functions(const std::string& source, bool cpp) {
    static const std::regex glsl_def(
        R"(^(?:float|int|bool|void|vec[234]|ivec[234]|mat[234]|[A-Z]\w*)\s+(\w+)\s*\()");
    static const std::regex cpp_def(
        R"(^(?:float|int|bool|void|glm::vec[234]|glm::ivec[234]|glm::mat[234]|[A-Z]\w*(?:<\w+>)?)\s+(?:\w+::)?(\w+)\s*\()");
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
    const fs::path technique = glsl.parent_path().filename();
    return fs::path(SHADERTWIN_SOURCE_DIR) / "kernels" / technique / (name + ".cpp");
}

std::vector<fs::path> glsl_files() {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(SHADERTWIN_SOURCE_DIR) / "glsl")) {
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
    std::vector<std::string> shaders;
    for (const fs::path& glsl : glsl_files()) shaders.push_back(glsl.filename().string());
    auto has = [&](const std::string& file) { return std::count(shaders.begin(), shaders.end(), file) == 1; };
    for (const auto& name : vertex_twin_names()) EXPECT_TRUE(has(name + ".vert")) << "vertex twin " << name;
    for (const auto& name : fragment_twin_names()) EXPECT_TRUE(has(name + ".frag")) << "fragment twin " << name;
}

// Every "Twin: path" in a shader names a file that exists, and it is the
// file the naming rule above gives.
TEST(Twins, EveryTwinPointerNamesItsFile) {
    static const std::regex pointer(R"(Twin:\s+(kernels/[\w/]+\.(?:cpp|h)))");
    const fs::path root(SHADERTWIN_SOURCE_DIR);
    for (const fs::path& glsl : glsl_files()) {
        const std::string source = read(glsl);
        std::smatch m;
        ASSERT_TRUE(std::regex_search(source, m, pointer)) << glsl << " has no 'Twin: kernels/...' line";
        EXPECT_TRUE(fs::exists(root / m[1].str())) << glsl << " points at missing " << m[1];
        EXPECT_EQ(root / m[1].str(), twin_of(glsl)) << glsl << " points at another twin";
    }
}

}  // namespace st
