// probe.cpp: `shadertwin probe` (probe.h). The GLSL side of a probe run is a
// rewrite of the fragment source: a prelude after #version defines
// ST_PROBE(name, value) as st_probe_<name>(value), which stores the value
// for the chosen name and is empty for the others; the shader's main() is
// renamed and a new main() calls it and then writes the stored value. The
// twin side wraps each fragment twin whose GLSL marks the probe in a
// ProbedFragment (shading/probe.h). Both run as `compare` runs them.
#include "app/commands/probe.h"

#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>

#include "app/backends.h"
#include "app/json_text.h"

#include <nlohmann/json.hpp>
#include "app/tool_data.h"
#include "gl/gl_renderer.h"
#include "gl/shader_files.h"
#include "kernels/registry.h"
#include "raster/cpu_renderer.h"
#include "scene/scene.h"
#include "shading/probe.h"
#include "shading/twin_library.h"

namespace st {

std::vector<std::string> probe_names(const std::string& source) {
    std::vector<std::string> names;
    std::istringstream in(source);
    std::string line;
    const std::regex mark(R"(\bST_PROBE\s*\(\s*([A-Za-z_][A-Za-z0-9_]*)\s*,)");
    while (std::getline(in, line)) {
        if (std::regex_search(line, std::regex(R"(^\s*#\s*define\s+ST_PROBE\b)"))) continue;
        for (auto it = std::sregex_iterator(line.begin(), line.end(), mark); it != std::sregex_iterator(); ++it) {
            const std::string name = (*it)[1];
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        }
    }
    return names;
}

std::string probe_source(const std::string& source, const std::vector<std::string>& names, const std::string& name) {
    // The colour output: `layout(location = 0) out vec4 c;`, or the only
    // output, vec4 and without a location (`out vec4 FragColor;`, which GL
    // puts at location 0).
    std::string output;
    std::smatch m;
    if (std::regex_search(source, m, std::regex(R"(layout\s*\(\s*location\s*=\s*0\s*\)\s*out\s+vec4\s+([A-Za-z_][A-Za-z0-9_]*)\s*;)"))) {
        output = m[1];
    } else {
        const std::regex any_output(R"((^|\n)[ \t]*(layout\s*\([^)]*\)\s*)?((highp|mediump|lowp)\s+)?out\s+(\w+)\s+(\w+)\s*;)");
        std::vector<std::smatch> outs;
        for (auto it = std::sregex_iterator(source.begin(), source.end(), any_output); it != std::sregex_iterator(); ++it)
            outs.push_back(*it);
        if (outs.size() == 1 && outs[0][5] == "vec4" && !outs[0][2].matched) output = outs[0][6];
    }
    if (output.empty())
        throw std::runtime_error("probe: the fragment program has no vec4 colour output (layout(location = 0) out vec4, "
                                 "or its one output) to write a probe to");
    const auto version_end = source.find('\n', source.find("#version"));
    if (source.find("#version") == std::string::npos || version_end == std::string::npos)
        throw std::runtime_error("probe: the fragment program has no #version line");
    std::string prelude =
        "#define ST_PROBE(name, value) st_probe_##name(value)\n"
        "vec4 st_probe_value = vec4(0.0);\n"
        "void st_probe_set(float v) { st_probe_value = vec4(v, 0.0, 0.0, 0.0); }\n"
        "void st_probe_set(vec2 v) { st_probe_value = vec4(v, 0.0, 0.0); }\n"
        "void st_probe_set(vec3 v) { st_probe_value = vec4(v, 0.0); }\n"
        "void st_probe_set(vec4 v) { st_probe_value = v; }\n"
        "void st_probe_set(int v) { st_probe_value = vec4(intBitsToFloat(v), 0.0, 0.0, 0.0); }\n";
    for (const std::string& n : names)
        prelude += "#define st_probe_" + n + "(v)" + (n == name ? " st_probe_set(v)" : "") + "\n";
    prelude += "#define main st_probe_main\n";
    // The prelude's lines do not count: the shader's keep their numbers.
    const std::string body = source.substr(version_end + 1);
    return source.substr(0, version_end + 1) + prelude + "#line 2\n" + body +
           "\n#undef main\nvoid main() {\n    st_probe_main();\n    " + output +
           " = st_probe_value;\n}\n";
}

namespace {

// The tool's twins, with the fragment programs in `probed` wrapped to write
// probe `name`.
class ProbeTwins final : public TwinLibrary {
public:
    ProbeTwins(std::set<std::string> probed, std::string name) : probed_(std::move(probed)), name_(std::move(name)) {}
    std::unique_ptr<VertexTwin> make_vertex(const std::string& n) const override { return twins().make_vertex(n); }
    std::unique_ptr<FragmentTwin> make_fragment(const std::string& n) const override {
        std::unique_ptr<FragmentTwin> twin = twins().make_fragment(n);
        if (!twin || !probed_.count(n)) return twin;
        return std::make_unique<ProbedFragment>(std::move(twin), name_);
    }
    std::vector<std::string> vertex_names() const override { return twins().vertex_names(); }
    std::vector<std::string> fragment_names() const override { return twins().fragment_names(); }

private:
    std::set<std::string> probed_;
    std::string name_;
};

std::string bits_of(float x) {
    uint32_t b;
    std::memcpy(&b, &x, 4);
    std::ostringstream s;
    s << "0x" << std::hex << std::setw(8) << std::setfill('0') << std::uppercase << b;
    return s.str();
}

std::string value_text(const float* v) {
    std::ostringstream s;
    s << std::setprecision(9) << "(" << v[0] << ", " << v[1] << ", " << v[2] << ", " << v[3] << ") ["
      << bits_of(v[0]) << " " << bits_of(v[1]) << " " << bits_of(v[2]) << " " << bits_of(v[3]) << "]";
    return s.str();
}

struct Difference {
    long pixels = 0;
    int x = -1, y = -1;  // the first, rows from the top
};

Difference differ(const Image& cpu, const Image& gl) {
    Difference d;
    for (int y = 0; y < cpu.height; ++y)
        for (int x = 0; x < cpu.width; ++x)
            if (std::memcmp(cpu.pixel(x, y), gl.pixel(x, y), 16) != 0) {
                if (d.pixels++ == 0) d.x = x, d.y = y;
            }
    return d;
}

}  // namespace

int cmd_probe(const std::string& scene_name, bool json, const CommonOptions& common) {
    const Scene scene = load_scene(scene_name, common.overrides);
    const ShaderFiles files(glsl_roots());
    // The probes in the order the programs' sources mark them, and which
    // programs mark each.
    std::vector<std::string> order;
    std::map<std::string, std::set<std::string>> programs_of;
    std::map<std::string, std::vector<std::string>> names_in;
    for (const Pass& pass : scene.frame.passes)
        for (const DrawCall& draw : pass.draws) {
            if (names_in.count(draw.fragment)) continue;
            const std::vector<std::string> names = probe_names(read_glsl_source(files.path(draw.fragment, ".frag")));
            names_in[draw.fragment] = names;
            for (const std::string& n : names) {
                if (!programs_of.count(n)) order.push_back(n);
                programs_of[n].insert(draw.fragment);
            }
        }
    if (order.empty())
        throw std::runtime_error("probe: " + scene.name +
                                 ": no fragment program marks a value with ST_PROBE(name, value) (docs/commands.md)");

    Backends backends(common.threads, common.gl_platform, glsl_roots());
    GlRenderer& gl = backends.gl();
    std::ostringstream report;
    int result = 0;
    nlohmann::json rows = nlohmann::json::array();
    for (const std::string& name : order) {
        const std::set<std::string>& probed = programs_of[name];
        gl.set_fragment_filter([&](const std::string& program, const std::string& source) {
            return probed.count(program) ? probe_source(source, names_in[program], name) : source;
        });
        const Image gl_image = gl.render(scene.frame);
        const ProbeTwins probe_twins(probed, name);
        CpuRenderer cpu(common.threads, probe_twins);
        const Image cpu_image = cpu.render(scene.frame);
        const Difference d = differ(cpu_image, gl_image);
        if (d.pixels == 0) {
            rows.push_back({{"probe", name}, {"pixels_differ", 0}});
            if (!json) std::cout << "same   " << name << "\n";
            continue;
        }
        const float* c = cpu_image.pixel(d.x, d.y);
        const float* g = gl_image.pixel(d.x, d.y);
        const int gl_y = cpu_image.height - 1 - d.y;  // window coordinates, as gl_FragCoord
        const auto bits4 = [](const float* v) {
            nlohmann::json b = nlohmann::json::array();
            for (int i = 0; i < 4; ++i) b.push_back(bits_of(v[i]));
            return b;
        };
        const auto floats4 = [](const float* v) {
            // JSON has no NaN or infinity: those are null, their bits say which.
            nlohmann::json f = nlohmann::json::array();
            for (int i = 0; i < 4; ++i) f.push_back(std::isfinite(v[i]) ? nlohmann::json(v[i]) : nlohmann::json());
            return f;
        };
        if (json) {
            rows.push_back({{"probe", name},
                            {"pixels_differ", d.pixels},
                            {"pixel", {d.x, gl_y}},
                            {"cpu", floats4(c)},
                            {"cpu_bits", bits4(c)},
                            {"gl", floats4(g)},
                            {"gl_bits", bits4(g)}});
        } else {
            std::cout << "DIFFER " << name << ": " << d.pixels << " of " << long(cpu_image.width) * cpu_image.height
                      << " pixels; first at pixel (" << d.x << ", " << gl_y << ") (gl_FragCoord.xy - 0.5)\n"
                      << "  cpu " << value_text(c) << "\n"
                      << "  gl  " << value_text(g) << "\n";
        }
        result = 1;
        break;
    }
    gl.set_fragment_filter({});
    if (json) {
        nlohmann::json summary = {{"scene", scene.name}, {"probes", rows}, {"first_differing", nullptr}};
        if (result) summary["first_differing"] = order[rows.size() - 1];
        std::cout << json_text(summary) << "\n";
    } else if (result == 0) {
        std::cout << "all " << order.size() << " probes agree bit for bit\n";
    }
    return result;
}

}  // namespace st
