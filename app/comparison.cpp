// comparison.cpp: see comparison.h.
#include "app/comparison.h"

#include <algorithm>

#include "app/tool_data.h"
#include "kernels/registry.h"
#include "image/image_io.h"

namespace st {

namespace {

std::string rendered_stem(const std::string& dir, const std::string& scene, Backend backend) {
    return dir + "/" + scene + "." + backend_name(backend);
}

void write_rendered_exr(const std::string& dir, const std::string& scene, Backend backend, const Image& image,
                        Backends& backends) {
    write_exr(rendered_stem(dir, scene, backend) + ".exr", image, backends.provenance(backend));
}

}  // namespace

std::string write_rendered(const std::string& dir, const std::string& scene, Backend backend,
                           const Image& image, Backends& backends, bool exr) {
    if (exr) write_rendered_exr(dir, scene, backend, image, backends);
    write_png(rendered_stem(dir, scene, backend) + ".png", image);
    return scene + "." + backend_name(backend) + ".png";
}

namespace {

// The twins the frame draws with that are still new-technique's skeleton,
// one failure line each (once per twin).
std::vector<std::string> unwritten_twins(const Frame& frame) {
    std::vector<std::string> out, seen;
    const auto note = [&](const std::string& stage, const char* unwritten) {
        if (!unwritten || std::find(seen.begin(), seen.end(), stage) != seen.end()) return;
        seen.push_back(stage);
        out.push_back("twin of " + stage + " not written yet: " + unwritten);
    };
    for (const Pass& pass : frame.passes)
        for (const DrawCall& draw : pass.draws) {
            if (const auto v = make_vertex_twin(draw.vertex)) note(draw.vertex + ".vert", v->unwritten());
            if (const auto f = make_fragment_twin(draw.fragment)) note(draw.fragment + ".frag", f->unwritten());
        }
    return out;
}

// The frame with every draw's search rays perturbed by `ulps` (the twins of
// searching programs read ulp_perturbation; GL never sees this frame).
Frame perturbed(const Frame& frame, int ulps) {
    Frame f = frame;
    for (Pass& pass : f.passes)
        for (DrawCall& d : pass.draws) {
            Uniform u{"ulp_perturbation", UniformType::Int, {}};
            u.value[0] = float(ulps);
            d.uniforms.push_back(u);
        }
    return f;
}

}  // namespace

SceneComparison compare_scene(const Scene& scene, Backends& backends, const std::string& out_dir, CompareFiles files) {
    SceneComparison c;
    c.scene = scene.name;
    const Rendered cpu = backends.render(Backend::Cpu, scene.frame);
    const Rendered gl = backends.render(Backend::Gl, scene.frame);
    const Frame coverage = coverage_frame(scene.frame);
    const Image cpu_cov = backends.render(Backend::Cpu, coverage).image;
    const Image gl_cov = backends.render(Backend::Gl, coverage).image;

    c.metrics = compare_images(cpu.image, gl.image);
    c.coverage_mismatch = st::coverage_mismatch(cpu_cov, gl_cov);
    const std::vector<uint8_t> over = over_1lsb(cpu.image, gl.image);
    c.over_1lsb = long(std::count(over.begin(), over.end(), uint8_t(1)));
    if (scene.criteria.condition_map) {
        // A pixel is ill-conditioned where a one-ULP change of the ray, either
        // way, moves the CPU result by more than 1 LSB.
        const Image plus = backends.render(Backend::Cpu, perturbed(scene.frame, 1)).image;
        const Image minus = backends.render(Backend::Cpu, perturbed(scene.frame, -1)).image;
        std::vector<uint8_t> map = over_1lsb(cpu.image, plus);
        const std::vector<uint8_t> other = over_1lsb(cpu.image, minus);
        for (size_t p = 0; p < map.size(); ++p) map[p] |= other[p];
        c.condition_pixels = long(std::count(map.begin(), map.end(), uint8_t(1)));
        for (size_t p = 0; p < map.size(); ++p) c.explained += over[p] && map[p];
        c.condition_png = scene.name + ".condition.png";
        std::vector<uint8_t> grey(map.size());
        for (size_t p = 0; p < map.size(); ++p) grey[p] = map[p] ? 255 : 0;
        write_png_bytes(out_dir + "/" + c.condition_png, cpu.image.width, cpu.image.height, 1, grey.data());
        c.failures = scene.criteria.failures(c.metrics, c.coverage_mismatch, c.over_1lsb, c.explained);
    } else {
        c.failures = scene.criteria.failures(c.metrics, c.coverage_mismatch);
    }
    for (const std::string& u : unwritten_twins(scene.frame)) c.failures.push_back(u);
    c.cpu_ms = cpu.ms;
    c.gl_ms = gl.ms;
    c.cpu_hash = pixel_hash(cpu.image);
    c.gl_hash = pixel_hash(gl.image);

    const bool share = files.share_identical_png && c.cpu_hash == c.gl_hash;
    c.cpu_png = write_rendered(out_dir, scene.name, Backend::Cpu, cpu.image, backends, false);
    c.gl_png = share ? c.cpu_png : write_rendered(out_dir, scene.name, Backend::Gl, gl.image, backends, false);
    c.diff_png = scene.name + ".diff.png";
    const auto heat = heat_map(cpu.image, gl.image);
    write_png_bytes(out_dir + "/" + c.diff_png, cpu.image.width, cpu.image.height, 3, heat.data());
    c.coverage_diff_png = scene.name + ".coverage-diff.png";
    const auto cov_heat = heat_map(cpu_cov, gl_cov);
    write_png_bytes(out_dir + "/" + c.coverage_diff_png, cpu.image.width, cpu.image.height, 3,
                    cov_heat.data());
    for (size_t i = 0; i < cpu.outputs.size(); ++i) {
        const NamedImage &a = cpu.outputs[i], &b = gl.outputs[i];
        OutputComparison o;
        o.name = a.name;
        o.metrics = compare_images(a.image, b.image);
        o.failures = scene.criteria.failures(o.metrics, 0);
        o.cpu_hash = pixel_hash(a.image);
        o.gl_hash = pixel_hash(b.image);
        const std::string stem = scene.name + "." + a.name;
        o.cpu_png = write_rendered(out_dir, stem, Backend::Cpu, a.image, backends, false);
        o.gl_png = files.share_identical_png && o.cpu_hash == o.gl_hash
                       ? o.cpu_png
                       : write_rendered(out_dir, stem, Backend::Gl, b.image, backends, false);
        o.diff_png = stem + ".diff.png";
        const auto h = heat_map(a.image, b.image);
        write_png_bytes(out_dir + "/" + o.diff_png, a.image.width, a.image.height, 3, h.data());
        c.outputs.push_back(std::move(o));
    }
    // The float images last, once the verdict is known.
    if (files.every_exr || !c.pass()) {
        write_rendered_exr(out_dir, scene.name, Backend::Cpu, cpu.image, backends);
        write_rendered_exr(out_dir, scene.name, Backend::Gl, gl.image, backends);
        for (size_t i = 0; i < cpu.outputs.size(); ++i) {
            const std::string stem = scene.name + "." + cpu.outputs[i].name;
            write_rendered_exr(out_dir, stem, Backend::Cpu, cpu.outputs[i].image, backends);
            write_rendered_exr(out_dir, stem, Backend::Gl, gl.outputs[i].image, backends);
        }
    }
    return c;
}

nlohmann::json metrics_json(const CompareMetrics& m) {
    return {{"width", m.width},
            {"height", m.height},
            {"identical_fraction_8bit", m.identical_fraction_8bit},
            {"max_diff_8bit", m.max_diff_8bit},
            {"identical_fraction_float", m.identical_fraction_float},
            {"max_rel_diff_float", m.max_rel_diff_float},
            {"max_abs_diff", m.max_abs_diff},
            {"mean_abs_diff", m.mean_abs_diff},
            {"rms_error", m.rms_error},
            {"psnr", m.psnr},
            {"nonfinite", m.nonfinite_a + m.nonfinite_b},
            {"nonfinite_mismatch", m.nonfinite_mismatch},
            {"nan_payload_only", m.nan_payload_only}};
}

void add_junit_cases(JunitReport& junit, const Scene& scene, const SceneComparison& c, const std::string& out_dir,
                     double seconds) {
    const std::string classname = "shadertwin." + scene.kind;
    const std::string reproduce = "reproduce: " + tool_name() + " compare " + scene.name + " --out " + out_dir;
    junit.add({classname, scene.name, seconds, c.failures,
               "heat map: " + out_dir + "/" + c.diff_png + "\ncoverage map: " + out_dir + "/" + c.coverage_diff_png +
                   "\n" + reproduce});
    for (const OutputComparison& o : c.outputs)
        junit.add({classname, scene.name + ":" + o.name, 0.0, o.failures,
                   "heat map: " + out_dir + "/" + o.diff_png + "\n" + reproduce});
}

nlohmann::json to_json(const SceneComparison& c) {
    nlohmann::json j = {{"scene", c.scene},
                        {"pass", c.pass()},
                        {"coverage_mismatch", c.coverage_mismatch}};
    j.update(metrics_json(c.metrics));
    j["pixels_over_1lsb"] = c.over_1lsb;
    if (c.condition_pixels >= 0) {
        j["condition_map_pixels"] = c.condition_pixels;
        j["explained_by_condition_map"] = c.explained;
    }
    j["failures"] = c.failures;
    j["cpu_ms"] = c.cpu_ms;
    j["gl_ms"] = c.gl_ms;
    j["cpu_hash"] = c.cpu_hash;
    j["gl_hash"] = c.gl_hash;
    j["outputs"] = nlohmann::json::array();
    for (const auto& o : c.outputs) {
        nlohmann::json jo = {{"name", o.name}, {"pass", o.failures.empty()}};
        jo.update(metrics_json(o.metrics));
        jo["failures"] = o.failures;
        jo["cpu_hash"] = o.cpu_hash;
        jo["gl_hash"] = o.gl_hash;
        j["outputs"].push_back(jo);
    }
    return j;
}

}  // namespace st
