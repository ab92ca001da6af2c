// How a Verilated tmc429_top is driven, shared by the bridge (rtl_bridge.cc) and the training
// run of the profile-guided build (pgo_train.cc, build/pgo.rs): the reset edge, the inputs of
// an edge and the falling and rising CLK edges.
#pragma once

// The function Verilator makes of the untraced model P's rising-edge logic, under a name the
// rising edge finds by its root class: one declaration per model, in the file that uses it.
#define TMC429_VL_POSEDGE(P)                                              \
    void P##___024root___nba_sequent__TOP__0(P##___024root *vlSelf);     \
    inline void tmc429_vl_posedge(P##___024root *r) { P##___024root___nba_sequent__TOP__0(r); }

namespace tmc429tb {

// The rising CLK edge: the flip-flops take the inputs set before it. With kDirect (an untraced
// model, declared with TMC429_VL_POSEDGE) and TMC429_VL_DIRECT_EDGE (build/vl_edge.rs: its
// eval at a rising clk runs that one function once and nothing else), the function is called
// without the eval's scheduling loop, and the clock's previous level is recorded as the eval
// would; otherwise the model is evaluated.
template <bool kDirect = false, class V>
void rising_edge(V &t) {
    t.rootp->clk = 1;
#if TMC429_VL_DIRECT_EDGE
    if constexpr (kDirect) {
        t.rootp->__Vtrigrprev__TOP__clk = 1;
        tmc429_vl_posedge(t.rootp);
        return;
    }
#endif
    t.eval();
}

// The reset state, as tmc429_model::Tmc429::new makes it: idle pins (nSCS_C = SCK_C = 1,
// switches open, REFR pulled up), then one CLK edge with rst = 1.
template <class V>
void reset_edge(V &t) {
    t.nscs_c = 1;
    t.sck_c = 1;
    t.sdi_c = 0;
    t.sdi_s = 0;
    t.ref1 = t.ref2 = t.ref3 = 0;
    t.refr1 = t.refr2 = t.refr3 = 1;
    t.rst = 1;
    t.clk = 0;
    t.eval();
    rising_edge(t);
    t.rst = 0;
}

// The input pins of the next edge, from any struct with their fields. The ports are set in
// the model's root class: the top class holds a reference to each, one more load per port.
template <class V, class In>
void set_inputs(V &top, const In &in) {
    auto &t = *top.rootp;
    t.nscs_c = in.nscs_c;
    t.sck_c = in.sck_c;
    t.sdi_c = in.sdi_c;
    t.sdi_s = in.sdi_s;
    t.ref1 = in.ref1;
    t.ref2 = in.ref2;
    t.ref3 = in.ref3;
    t.refr1 = in.refr1;
    t.refr2 = in.refr2;
    t.refr3 = in.refr3;
}

// The falling CLK edge of a model built without trace. With TMC429_VL_TRIGRPREV (Verilator
// 5.006) without an eval: nothing in rtl/ acts on the falling edge of clk, so the eval at
// clk = 0 would only record the clock level for Verilator's edge detection; it is set directly
// (the eval at clk = 1 settles whatever the new inputs drive before the edge's flops take
// them, as an eval at clk = 0 would).
template <class V>
void falling_edge(V &t) {
    t.rootp->clk = 0;
#if TMC429_VL_TRIGRPREV
    t.rootp->__Vtrigrprev__TOP__clk = 0;
#else
    t.eval();
#endif
}

}  // namespace tmc429tb
