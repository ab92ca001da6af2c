// Bridge between the Rust harness and the Verilated RTL models (see src/rtl.rs).
#pragma once
#include <cstdint>
#include <memory>
#include "rust/cxx.h"

namespace tmc429tb {

struct RtlInputs;
struct RtlOutputs;
struct RtlProbes;

// One Verilated tmc429_top. Construction applies one CLK edge with rst = 1, so the model
// starts in the reset state, like tmc429_model::Tmc429::new.
class RtlSim {
public:
    virtual ~RtlSim() {}
    // One rising CLK edge: inputs applied before it, outputs and probes after it.
    virtual void tick(const RtlInputs &in, RtlOutputs &out, RtlProbes &probes) = 0;
    // One rising CLK edge, like tick, without copying out: whether the outputs and probes
    // after it are exactly `out` and `probes` (what tick would have written).
    virtual bool tick_check(const RtlInputs &in, const RtlOutputs &out, const RtlProbes &probes) = 0;
    // Outputs and probes of the current state, without a clock edge.
    virtual void peek(RtlOutputs &out, RtlProbes &probes) const = 0;
    // Starts Verilator's VCD trace of every RTL signal; time unit 1 ps, one CLK period
    // = period_ps. Returns false if the file cannot be opened or the model has no trace.
    virtual bool trace_open(rust::Str path, uint64_t period_ps) = 0;
    virtual void trace_close() = 0;
    virtual uint64_t cycle() const = 0;
};

// variant: 0 TMC428, 1 TMC429, 2 TMC4210, 3 TMC429 with PLANT_BUG_STATUS. traced: the model
// built with --trace (trace_open works; slower), else the one without (trace_open returns
// false). Returns nullptr for an unknown variant.
std::unique_ptr<RtlSim> new_rtl(uint32_t variant, bool traced);

}  // namespace tmc429tb
