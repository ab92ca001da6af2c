#!/usr/bin/env python3
"""A copy of this repository's RTL with a planted bug, for the examples of
docs/verify-your-rtl.md: the harnesses must catch it at the cycle the golden model predicts.

    python examples/verify/plant_bug.py OUT_DIR [--rtl DIR] [--pin poscmp] [--expect-cycle ...]

Copies every Verilog file and header of the RTL directory (default rtl/) to OUT_DIR, renames the chip's
pins-only top ``tmc429_chip`` to ``tmc429_chip_unplanted`` in the copy, and adds
``tmc429_chip_planted.v``: a ``tmc429_chip`` with the same ports and parameters (as the
simulator's front end finds them) around it, whose output PIN is one CLK late (an extra
register). The bug shows at the first edge after which the model's PIN changes.

``--expect-cycle VARIANT PROFILE SEED CYCLES`` prints that edge instead (the golden model run on
the seeded stimulus of ``tmc429 cosim``), or exits 1 if PIN does not change within CYCLES.
"""

import argparse
import re
import shutil
import sys
import tempfile
from pathlib import Path

import tmc429
from tmc429.cocotb import ports

TOP = "tmc429_chip"


def first_change(variant: str, profile: str, seed: int, cycles: int, pin: str):
    """The first edge after which the model's output `pin` differs from before it."""
    bit = 1 << tmc429.OUTPUT_PINS.index(pin)
    ref = tmc429.Reference(variant, profile, seed)
    before = ref.output_word & bit
    for n in range(1, cycles + 1):
        ref.step()
        if ref.output_word & bit != before:
            return n
    return None


def plant(rtl: Path, out: Path, pin: str) -> Path:
    sources = sorted(rtl.glob("*.v"))
    if not sources:
        sys.exit(f"plant_bug: no Verilog files in {rtl}")
    sim = "icarus" if shutil.which("iverilog") else "verilator"
    with tempfile.TemporaryDirectory() as work:
        d = ports.design(sim, sources, TOP, {}, Path(work))
    if pin not in [p.name for p in d.ports if p.direction == "output"]:
        sys.exit(f"plant_bug: {TOP} has no output '{pin}'")
    out.mkdir(parents=True, exist_ok=True)
    renamed = 0
    for s in sources:
        text = s.read_text()
        text, n = re.subn(rf"\bmodule\s+{TOP}\b", f"module {TOP}_unplanted", text)
        renamed += n
        (out / s.name).write_text(text)
    for h in sorted(rtl.glob("*.vh")):   # the headers the sources include (tmc429_regmap.vh)
        shutil.copyfile(h, out / h.name)
    if renamed != 1:
        sys.exit(f"plant_bug: expected one 'module {TOP}' in {rtl}, found {renamed}")
    params = ", ".join(f"parameter {p} = 1" for p in d.parameters)
    decl = ",\n".join(f"    {p.direction} wire {'[%d:0] ' % (p.width - 1) if p.width > 1 else ''}{p.name}" for p in d.ports)
    conn = ", ".join(f".{p.name}({p.name + '_on_time' if p.name == pin else p.name})" for p in d.ports)
    pass_params = ", ".join(f".{p}({p})" for p in d.parameters)
    clk = "clk"
    v = f"""// The planted bug of the examples (examples/verify/plant_bug.py): {pin} one CLK late.
`timescale 1ns / 1ps
`default_nettype none
module {TOP} {'#(' + params + ') ' if params else ''}(
{decl}
);
    wire {pin}_on_time;
    {TOP}_unplanted {'#(' + pass_params + ') ' if pass_params else ''}u_chip ({conn});
    reg {pin}_late = 1'b0;
    always @(posedge {clk}) {pin}_late <= {pin}_on_time;  // the planted bug
    assign {pin} = {pin}_late;
endmodule
`default_nettype wire
"""
    path = out / f"{TOP}_planted.v"
    path.write_text(v)
    return path


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("out", type=Path, nargs="?")
    p.add_argument("--rtl", type=Path, default=Path(__file__).resolve().parents[2] / "rtl")
    p.add_argument("--pin", default="poscmp", choices=tmc429.OUTPUT_PINS)
    p.add_argument("--expect-cycle", nargs=4, metavar=("VARIANT", "PROFILE", "SEED", "CYCLES"))
    a = p.parse_args()
    if a.expect_cycle:
        variant, profile, seed, cycles = a.expect_cycle
        n = first_change(variant, profile, int(seed), int(cycles), a.pin)
        if n is None:
            print(f"{a.pin} does not change within {cycles} cycles", file=sys.stderr)
            return 1
        print(n)
        return 0
    if a.out is None:
        p.error("OUT_DIR is required")
    print(plant(a.rtl, a.out, a.pin))
    return 0


if __name__ == "__main__":
    sys.exit(main())
