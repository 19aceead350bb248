// probe.cpp: the thread's probe sink (probe.h).
#include "shading/probe.h"

namespace st {

ProbeSink*& current_probe_sink() {
    thread_local ProbeSink* sink = nullptr;
    return sink;
}

}  // namespace st
