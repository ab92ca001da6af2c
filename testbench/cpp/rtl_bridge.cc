// Bridge between the Rust harness and the Verilated RTL models (see src/rtl.rs).
#include "tmc429-testbench/cpp/rtl_bridge.h"
#include "tmc429-testbench/src/rtl.rs.h"

#include <fstream>
#include <string>

#include "verilated.h"
#include "verilated_vcd_c.h"
#include "Vtmc429_428.h"
#include "Vtmc429_429.h"
#include "Vtmc429_4210.h"
#include "Vtmc429_429_bug_status.h"
#include "Vtmc429_428_tr.h"
#include "Vtmc429_429_tr.h"
#include "Vtmc429_4210_tr.h"
#include "Vtmc429_429_bug_status_tr.h"
#include "Vtmc429_428___024root.h"
#include "Vtmc429_429___024root.h"
#include "Vtmc429_4210___024root.h"
#include "Vtmc429_429_bug_status___024root.h"
#include "Vtmc429_428_tr___024root.h"
#include "Vtmc429_429_tr___024root.h"
#include "Vtmc429_4210_tr___024root.h"
#include "Vtmc429_429_bug_status_tr___024root.h"
#include "tmc429-testbench/cpp/vl_pins.h"

TMC429_VL_POSEDGE(Vtmc429_428)
TMC429_VL_POSEDGE(Vtmc429_429)
TMC429_VL_POSEDGE(Vtmc429_4210)
TMC429_VL_POSEDGE(Vtmc429_429_bug_status)

namespace tmc429tb {
namespace {

inline int32_t sext(uint32_t v, int bits) {
    return static_cast<int32_t>(v << (32 - bits)) >> (32 - bits);
}

#define TMC429_READ_MOTOR(N)                                              \
    p.x_target = t.probe_m##N##_x_target;                                 \
    p.x_actual = t.probe_m##N##_x_actual;                                 \
    p.v_internal = sext(t.probe_m##N##_v_internal, 20);                   \
    p.v_target = sext(t.probe_m##N##_v_target, 12);                       \
    p.a_actual = sext(t.probe_m##N##_a_actual, 12);                       \
    p.ustep = t.probe_m##N##_ustep;                                       \
    p.step = t.probe_m##N##_step;                                         \
    p.dir = t.probe_m##N##_dir;                                           \
    p.pulse_acc = t.probe_m##N##_pulse_acc;

// V: a Verilated model; kTrace: built with --trace (the `…_tr` models of build.rs), else
// trace_open fails.
// The fields TMC429_READ_MOTOR(N) writes to p, compared with p (a bool).
#define TMC429_SAME_MOTOR(N, p)                                                            \
    ((t.probe_m##N##_x_target == p.x_target) & (t.probe_m##N##_x_actual == p.x_actual) &   \
     (sext(t.probe_m##N##_v_internal, 20) == p.v_internal) &                               \
     (sext(t.probe_m##N##_v_target, 12) == p.v_target) &                                   \
     (sext(t.probe_m##N##_a_actual, 12) == p.a_actual) & (t.probe_m##N##_ustep == p.ustep) & \
     (t.probe_m##N##_step == p.step) & (t.probe_m##N##_dir == p.dir) &                     \
     (t.probe_m##N##_pulse_acc == p.pulse_acc))

template <class V, bool kTrace>
class RtlSimImpl final : public RtlSim {
public:
    RtlSimImpl() : ctx_(new VerilatedContext) {
        ctx_->traceEverOn(kTrace);
        top_.reset(new V(ctx_.get(), "rtl"));
        reset_edge(*top_);
    }
    ~RtlSimImpl() override {
        trace_close();
        top_->final();
    }

    void tick(const RtlInputs &in, RtlOutputs &out, RtlProbes &pr) override {
        edge(in);
        peek(out, pr);
    }

    bool tick_check(const RtlInputs &in, const RtlOutputs &out, const RtlProbes &pr) override {
        edge(in);
        return same(out, pr);
    }

    // Whether peek would give exactly `out` and `pr`: every field peek writes, compared.
    bool same(const RtlOutputs &out, const RtlProbes &pr) const {
        const auto &t = *top_->rootp;
        bool s = (t.nint_sdo_c == out.nint_sdo_c) & (t.sdoz_c == out.sdoz_c) &
                 (t.sdoz_c_oe == out.sdoz_c_oe) & (t.nscs_s == out.nscs_s) &
                 (t.sck_s == out.sck_s) & (t.sdo_s == out.sdo_s) & (t.sdi_s_o == out.sdi_s_o) &
                 (t.sdi_s_oe == out.sdi_s_oe) & (t.nscs2 == out.nscs2) &
                 (t.nscs3 == out.nscs3) & (t.poscmp == out.poscmp);
        s &= TMC429_SAME_MOTOR(0, pr.m0) & TMC429_SAME_MOTOR(1, pr.m1) & TMC429_SAME_MOTOR(2, pr.m2);
        s &= (t.probe_chain_state == pr.chain.state) & (t.probe_chain_cell == pr.chain.cell) &
             (t.probe_chain_motor == pr.chain.motor) &
             (t.probe_chain_bit_count == pr.chain.bit_count) &
             (t.probe_chain_pending == pr.chain.pending) &
             (t.probe_chain_cover_waiting == pr.chain.cover_waiting) &
             (t.probe_chain_readback == pr.chain.readback);
        s &= (t.probe_prescaler == pr.prescaler) & (t.probe_power_down == pr.power_down) &
             (t.probe_status == pr.status);
        return s;
    }

private:
    // One rising CLK edge with the inputs `in`.
    void edge(const RtlInputs &in) {
        V &t = *top_;
        set_inputs(t, in);
        if constexpr (kTrace) {
            t.clk = 0;
            t.eval();
            if (tfp_) tfp_->dump(cycle_ * period_ + period_ / 2);
        } else {
            falling_edge(t);
        }
        rising_edge<!kTrace>(t);
        ++cycle_;
        if constexpr (kTrace) {
            if (tfp_) tfp_->dump(cycle_ * period_);
        }
    }

public:

    void peek(RtlOutputs &out, RtlProbes &pr) const override {
        const auto &t = *top_->rootp;
        out.nint_sdo_c = t.nint_sdo_c;
        out.sdoz_c = t.sdoz_c;
        out.sdoz_c_oe = t.sdoz_c_oe;
        out.nscs_s = t.nscs_s;
        out.sck_s = t.sck_s;
        out.sdo_s = t.sdo_s;
        out.sdi_s_o = t.sdi_s_o;
        out.sdi_s_oe = t.sdi_s_oe;
        out.nscs2 = t.nscs2;
        out.nscs3 = t.nscs3;
        out.poscmp = t.poscmp;

        {
            RtlMotorProbe &p = pr.m0;
            TMC429_READ_MOTOR(0)
        }
        {
            RtlMotorProbe &p = pr.m1;
            TMC429_READ_MOTOR(1)
        }
        {
            RtlMotorProbe &p = pr.m2;
            TMC429_READ_MOTOR(2)
        }
        pr.chain.state = t.probe_chain_state;
        pr.chain.cell = t.probe_chain_cell;
        pr.chain.motor = t.probe_chain_motor;
        pr.chain.bit_count = t.probe_chain_bit_count;
        pr.chain.pending = t.probe_chain_pending;
        pr.chain.cover_waiting = t.probe_chain_cover_waiting;
        pr.chain.readback = t.probe_chain_readback;
        pr.prescaler = t.probe_prescaler;
        pr.power_down = t.probe_power_down;
        pr.status = t.probe_status;
    }

    bool trace_open(rust::Str path, uint64_t period_ps) override {
        trace_close();
        if constexpr (!kTrace) {
            return false;
        } else {
            std::string p(path.data(), path.size());
            {
                // VerilatedVcdC aborts the process on an unwritable path: check first
                std::ofstream probe(p, std::ios::out | std::ios::trunc);
                if (!probe) return false;
            }
            period_ = period_ps ? period_ps : 2;
            tfp_.reset(new VerilatedVcdC);
            top_->trace(tfp_.get(), 99);
            tfp_->set_time_unit("1ps");
            tfp_->set_time_resolution("1ps");
            tfp_->open(p.c_str());
            if (!tfp_->isOpen()) {
                tfp_.reset();
                return false;
            }
            tfp_->dump(cycle_ * period_);
            return true;
        }
    }

    void trace_close() override {
        if (tfp_) {
            tfp_->close();
            tfp_.reset();
        }
    }

    uint64_t cycle() const override { return cycle_; }

private:
    std::unique_ptr<VerilatedContext> ctx_;
    std::unique_ptr<V> top_;
    std::unique_ptr<VerilatedVcdC> tfp_;
    uint64_t cycle_ = 0;
    uint64_t period_ = 2;
};

}  // namespace

std::unique_ptr<RtlSim> new_rtl(uint32_t variant, bool traced) {
    if (traced) {
        switch (variant) {
        case 0: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_428_tr, true>());
        case 1: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_429_tr, true>());
        case 2: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_4210_tr, true>());
        case 3: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_429_bug_status_tr, true>());
        default: return nullptr;
        }
    }
    switch (variant) {
    case 0: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_428, false>());
    case 1: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_429, false>());
    case 2: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_4210, false>());
    case 3: return std::unique_ptr<RtlSim>(new RtlSimImpl<Vtmc429_429_bug_status, false>());
    default: return nullptr;
    }
}

}  // namespace tmc429tb
