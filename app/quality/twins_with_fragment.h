// twins_with_fragment.h: the built-in twins (kernels/registry.h) plus
// fragment programs of the app's own, CPU-only yardsticks that mirror no
// GLSL (relief_exact.h, thin_slab_exact.h). A frame names one in place of
// the program it stands for; every other name resolves as usual.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernels/registry.h"
#include "shading/twin_library.h"

namespace st {

class TwinsWithFragment : public TwinLibrary {
public:
    using Make = std::function<std::unique_ptr<FragmentTwin>()>;
    explicit TwinsWithFragment(std::vector<std::pair<std::string, Make>> programs) : programs_(std::move(programs)) {}
    TwinsWithFragment(std::string name, Make make) : programs_{{std::move(name), std::move(make)}} {}

    std::unique_ptr<VertexTwin> make_vertex(const std::string& name) const override { return twins().make_vertex(name); }
    std::unique_ptr<FragmentTwin> make_fragment(const std::string& name) const override {
        for (const auto& [own, make] : programs_)
            if (name == own) return make();
        return twins().make_fragment(name);
    }
    std::vector<std::string> vertex_names() const override { return twins().vertex_names(); }
    std::vector<std::string> fragment_names() const override {
        std::vector<std::string> names = twins().fragment_names();
        for (const auto& program : programs_) names.push_back(program.first);
        return names;
    }

private:
    std::vector<std::pair<std::string, Make>> programs_;
};

}  // namespace st
