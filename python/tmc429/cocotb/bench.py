"""The cocotb test the harness runs inside the simulator: the design and the golden model in
lock-step on the seeded stimulus of ``tmc429 cosim``.

Timing (docs/verify-your-rtl.md): CLK rises at the start of each period; at the falling edge
the harness reads the design's outputs of the last rising edge (C1: register outputs), compares
them with the model's, and applies the inputs of the next rising edge, so that no input changes
with a rising edge. Reset: ``rst`` high for ``reset_cycles`` rising edges with the idle inputs,
then the reset states are compared (cycle 0) before the first edge (C2).
"""

import json
import os
import time

import cocotb
from cocotb.triggers import Timer

import tmc429

CONFIG_ENV = "TMC429_COCOTB_CONFIG"


def _word(handle, what):
    """The value of a packed pin vector; X or Z bits are a mismatch of their own."""
    v = handle.value
    try:
        return int(v), None
    except ValueError:
        names = tmc429.OUTPUT_PINS if what == "out" else tmc429.INPUT_PINS
        bits = v.binstr[::-1]
        bad = [f"{n}={b}" for n, b in zip(names, bits) if b not in "01"]
        return None, ", ".join(bad)


@cocotb.test()
async def lockstep(dut):
    """The design and the golden model in lock-step; stops at the first mismatch."""
    with open(os.environ[CONFIG_ENV]) as f:
        cfg = json.load(f)
    ref = tmc429.Reference(cfg["variant"], cfg["profile"], cfg["seed"], cfg["absent"])
    clk, rst, pins_in, pins_out = dut.clk, dut.rst, dut.pins_in, dut.pins_out
    half = Timer(cfg["half_period_ps"], "ps")
    cycles = cfg["cycles"]
    result = {"xz": None}

    pins_in.value = ref.idle_word
    rst.value = 1
    clk.value = 0
    await half
    for _ in range(cfg["reset_cycles"]):
        clk.value = 1
        await half
        clk.value = 0
        await half
    rst.value = 0
    t0 = time.perf_counter()
    out, xz = _word(pins_out, "out")
    ok = xz is None and ref.check(out)
    if ok:
        pins_in.value = ref.step(out)
    n = 0
    while ok and n < cycles:
        clk.value = 1
        await half
        n += 1
        out, xz = _word(pins_out, "out")
        if xz is not None:
            ok = False
            break
        if n == cycles:
            ok = ref.check(out)
            break
        w = ref.exchange(out)
        if w is None:
            ok = False
            break
        pins_in.value = w
        clk.value = 0
        await half
    seconds = time.perf_counter() - t0
    if xz is not None:
        result["xz"] = {"cycle": ref.cycle, "pins": xz}
    result.update(
        cycles=ref.cycle,
        frames=ref.frames,
        pin_changes=ref.pin_changes,
        mismatch_cycle=ref.mismatch_cycle,
        report=ref.mismatch_report(cfg["label"]),
        coverage=ref.coverage(),
        coverage_table=ref.coverage_table(),
        missed=ref.missed_bins(),
        seconds=seconds,
    )
    with open(cfg["result"], "w") as f:
        json.dump(result, f)
    assert ok, f"mismatch at cycle {ref.cycle} (report: {cfg['result']})"
