// probe.h: the twin's side of `shadertwin probe` (app/commands/probe.cpp):
// a fragment twin marks an intermediate value with frag.probe("name", v)
// where its GLSL has ST_PROBE(name, v). In a normal run nothing is
// recorded (one thread-local load and a test). In a probe run the command
// wraps the twin (ProbedFragment below): while the twin runs, the probe of
// the chosen name records its value for the lanes that reach it (the last
// write wins, as in the GLSL the probe run builds), and the twin's colour
// is replaced by that value, zero where the probe was not reached, as the
// GLSL's is. So both backends write only the probed value and the command
// compares it bit for bit.
#pragma once

#include <memory>
#include <string>

#include "shading/program.h"

namespace st {

// The probe being recorded on this thread, if any.
struct ProbeSink {
    std::string name;
    Vec4 value{Float(0.0f)};
};
ProbeSink*& current_probe_sink();

// A float, vec2, vec3, vec4 or int probe value as the four floats the probe
// run writes (GLSL: st_probe_set in the probe command's prelude): the
// components, zeros after them; an int's bits as a float's.
inline Vec4 probe_value(Float v) { return Vec4(v, Float(0.0f), Float(0.0f), Float(0.0f)); }
inline Vec4 probe_value(const Vec2& v) { return Vec4(v, Float(0.0f), Float(0.0f)); }
inline Vec4 probe_value(const Vec3& v) { return Vec4(v, Float(0.0f)); }
inline Vec4 probe_value(const Vec4& v) { return v; }
inline Vec4 probe_value(Int v) { return probe_value(simd::bit_cast_float(v)); }

// GLSL ST_PROBE(name, value) at a point every active lane reaches (the
// invocation's control-flow mask decides which lanes record), or only
// where `where` holds (a probe inside an `if` the twin writes as a select).
template <class V> void probe(const Fragment& frag, const char* name, const V& value, Mask where = Mask(true)) {
    ProbeSink* sink = current_probe_sink();
    if (!sink || sink->name != name) return;
    const Mask lanes = frag.exec().active() && where;
    sink->value = select(lanes, probe_value(value), sink->value);
}

// A fragment twin run for a probe: shade() records the probe `name` and
// writes its value as the colour.
class ProbedFragment final : public FragmentTwin {
public:
    ProbedFragment(std::unique_ptr<FragmentTwin> twin, std::string name)
        : twin_(std::move(twin)), name_(std::move(name)) {}
    void bind(const Bindings& b) override { twin_->bind(b); }
    uint32_t inputs_read() const override { return twin_->inputs_read(); }
    Interpolations interpolations() const override { return twin_->interpolations(); }
    SlotNames input_names() const override { return twin_->input_names(); }
    int output_count() const override { return twin_->output_count(); }
    void shade(const FragmentLanes& in, FragmentResult& out) const override {
        ProbeSink sink{name_};
        ProbeSink* const saved = current_probe_sink();
        current_probe_sink() = &sink;
        twin_->shade(in, out);
        current_probe_sink() = saved;
        out.colour = sink.value;
    }

private:
    std::unique_ptr<FragmentTwin> twin_;
    std::string name_;
};

}  // namespace st
