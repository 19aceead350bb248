// twins_with_fragment.h: the built-in twins (kernels/registry.h) plus one
// fragment program of the app's own, a CPU-only yardstick that mirrors no
// GLSL (relief_exact.h, thin_slab_exact.h). A frame names it in place of
// the program it stands for; every other name resolves as usual.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kernels/registry.h"
#include "shading/twin_library.h"

namespace st {

class TwinsWithFragment : public TwinLibrary {
public:
    using Make = std::function<std::unique_ptr<FragmentTwin>()>;
    TwinsWithFragment(std::string name, Make make) : name_(std::move(name)), make_(std::move(make)) {}

    std::unique_ptr<VertexTwin> make_vertex(const std::string& name) const override { return twins().make_vertex(name); }
    std::unique_ptr<FragmentTwin> make_fragment(const std::string& name) const override {
        return name == name_ ? make_() : twins().make_fragment(name);
    }
    std::vector<std::string> vertex_names() const override { return twins().vertex_names(); }
    std::vector<std::string> fragment_names() const override {
        std::vector<std::string> names = twins().fragment_names();
        names.push_back(name_);
        return names;
    }

private:
    std::string name_;
    Make make_;
};

}  // namespace st
