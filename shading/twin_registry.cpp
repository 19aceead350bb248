// twin_registry.cpp: see twin_registry.h.
#include "shading/twin_registry.h"

#include <stdexcept>

namespace st {

namespace {

template <class Factory>
void add(std::map<std::string, Factory>& table, const char* stage, const std::string& name, Factory factory) {
    if (name.empty()) throw std::invalid_argument(std::string(stage) + " twin with an empty name");
    if (!factory) throw std::invalid_argument(std::string(stage) + " twin '" + name + "' has no factory");
    if (!table.emplace(name, std::move(factory)).second)
        throw std::invalid_argument(std::string(stage) + " twin '" + name + "' registered twice");
}

template <class Twin, class Factory>
std::unique_ptr<Twin> make(const std::map<std::string, Factory>& table, const std::string& name) {
    const auto it = table.find(name);
    return it == table.end() ? nullptr : it->second();
}

template <class Factory>
std::vector<std::string> names(const std::map<std::string, Factory>& table) {
    std::vector<std::string> out;
    for (const auto& entry : table) out.push_back(entry.first);
    return out;
}

}  // namespace

void TwinRegistry::add_vertex(const std::string& name, VertexFactory factory) {
    add(vertex_, "vertex", name, std::move(factory));
}
void TwinRegistry::add_fragment(const std::string& name, FragmentFactory factory) {
    add(fragment_, "fragment", name, std::move(factory));
}
std::unique_ptr<VertexTwin> TwinRegistry::make_vertex(const std::string& name) const {
    return make<VertexTwin>(vertex_, name);
}
std::unique_ptr<FragmentTwin> TwinRegistry::make_fragment(const std::string& name) const {
    return make<FragmentTwin>(fragment_, name);
}
std::vector<std::string> TwinRegistry::vertex_names() const { return names(vertex_); }
std::vector<std::string> TwinRegistry::fragment_names() const { return names(fragment_); }

}  // namespace st
