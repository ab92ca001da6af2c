"""``python -m tmc429.cocotb``: a Verilog design and the golden model in lock-step under cocotb.

    python -m tmc429.cocotb --sources FILES --toplevel NAME [--parameter K=V] \\
        --sim icarus|verilator --seed S --cycles N [--port-map FILE]

Exit status 0 only with 0 mismatches, 1 on a mismatch, 2 on bad input (an unknown option or
pin, a port the design lacks, a pin without a port, a design that does not compile).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import shutil
import sys
from pathlib import Path
from typing import Dict, Iterator, List, Optional, Sequence

from .. import PROFILES, VARIANTS
from . import ports
from .ports import UsageError

#: CLK half period of the simulation (ns); the design sees edges, not time.
HALF_PERIOD_PS = 5000
RESET_CYCLES = 2
SIMULATORS = {
    "icarus": ("iverilog", "install Icarus Verilog (Debian: apt-get install iverilog)"),
    "verilator": ("verilator", "install Verilator 5 (Debian: apt-get install verilator)"),
}


def parse_args(argv: Optional[Sequence[str]]) -> argparse.Namespace:
    p = argparse.ArgumentParser(
        prog="python -m tmc429.cocotb",
        description="Runs a Verilog design with the TMC429 pins and the tmc429 golden model in lock-step under "
        "cocotb, on the seeded stimulus of `tmc429 cosim`, and compares every output pin after every CLK edge.",
    )
    p.add_argument("--sources", nargs="+", required=True, metavar="FILE", help="the design's Verilog files")
    p.add_argument("--toplevel", required=True, metavar="NAME", help="the design's top module")
    p.add_argument("--parameter", action="append", default=[], metavar="K=V", help="a parameter of the top module (repeatable)")
    p.add_argument("--sim", required=True, choices=sorted(SIMULATORS), help="the simulator")
    p.add_argument("--seed", type=int, default=1, help="seed of the stimulus; the same as `tmc429 cosim --seed` (default 1)")
    p.add_argument("--cycles", type=int, default=50_000, help="CLK cycles after reset (default 50000)")
    p.add_argument("--port-map", type=Path, metavar="FILE", help="pin-to-port map for a design that names the pins differently")
    p.add_argument("--chip", default="tmc429", choices=VARIANTS, help="the variant the design implements (default tmc429)")
    p.add_argument("--profile", default="motion", choices=PROFILES, help="stimulus profile, as `tmc429 cosim --profile` (default motion)")
    p.add_argument("--coverage", action="store_true", help="print the coverage table and the bins never hit")
    p.add_argument("--build-dir", type=Path, default=Path("tmc429-cocotb"), metavar="DIR", help="where to build (default ./tmc429-cocotb)")
    a = p.parse_args(argv)
    if a.cycles < 1:
        p.error("--cycles: expected at least 1")
    if a.seed < 0:
        p.error("--seed: expected 0 or more")
    return a


def parameters(items: List[str]) -> Dict[str, str]:
    out: Dict[str, str] = {}
    for item in items:
        k, eq, v = item.partition("=")
        if not eq or not k.strip() or not v.strip() or not k.strip().isidentifier():
            raise UsageError(f"--parameter {item}: expected NAME=VALUE, e.g. CHIP=1")
        out[k.strip()] = v.strip()
    return out


@contextlib.contextmanager
def output_to(log: Path) -> Iterator[None]:
    """The simulator's and cocotb's output into `log` (this process's stdout and stderr too)."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with open(log, "w") as f:
        os.dup2(f.fileno(), 1)
        os.dup2(f.fileno(), 2)
        try:
            yield
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])


def tail(log: Path, n: int = 25) -> str:
    lines = log.read_text(errors="replace").splitlines()
    return "\n".join("  " + l for l in lines[-n:])


def prepare(a: argparse.Namespace) -> dict:
    """Checks the input, finds the design's ports, writes the wrapper; the run's configuration."""
    sources = [Path(s) for s in a.sources]
    for s in sources:
        if not s.is_file():
            raise UsageError(f"--sources: {s}: no such file")
    tool, hint = SIMULATORS[a.sim]
    if shutil.which(tool) is None:
        raise UsageError(f"--sim {a.sim}: {tool} not found: {hint}")
    try:
        import cocotb  # noqa: F401
    except ImportError:
        raise UsageError("cocotb is not installed: pip install 'tmc429[cocotb]' (docs/verify-your-rtl.md)") from None
    params = parameters(a.parameter)
    pmap = ports.parse_port_map(a.port_map) if a.port_map else ports.PortMap()
    build = (a.build_dir / f"{a.toplevel}-{a.sim}").resolve()
    build.mkdir(parents=True, exist_ok=True)
    found = ports.design(a.sim, sources, a.toplevel, params, build)
    conns = ports.connect(found.ports, pmap, a.toplevel)
    wrapper = build / f"{ports.WRAPPER}.v"
    wrapper.write_text(ports.wrapper(a.toplevel, params, conns, pmap.ties))
    label = a.toplevel + "".join(f" {k}={v}" for k, v in params.items())
    return {
        "sources": [str(s.resolve()) for s in sources] + [str(wrapper)],
        "includes": [str(d) for d in ports.include_dirs(sources)],
        "build": str(build),
        "variant": a.chip,
        "profile": a.profile,
        "seed": a.seed,
        "cycles": a.cycles,
        "absent": list(ports.absent_outputs(conns)),
        "label": f"{label}, {a.sim}",
        "half_period_ps": HALF_PERIOD_PS,
        "reset_cycles": RESET_CYCLES,
        "result": str(build / "result.json"),
    }


def simulate(sim: str, cfg: dict) -> dict:
    """Builds the wrapper and the design, runs the lock-step test; its result."""
    import warnings

    with warnings.catch_warnings():
        # cocotb 1.8 and 1.9 call their runner experimental; the harness uses build and test only.
        warnings.simplefilter("ignore")
        from cocotb.runner import get_runner

    build = Path(cfg["build"])
    result = Path(cfg["result"])
    result.unlink(missing_ok=True)
    (build / "config.json").write_text(json.dumps(cfg))
    runner = get_runner(sim)
    if sim == "icarus":
        args = ["-s", ports.WRAPPER]
    else:
        # --timescale: the wrapper's, for the design's modules that have none (IEEE 1800-2017
        # §3.14.2.3 wants one for all or none)
        args = ["-Wno-fatal", "-O3", "--x-assign", "fast", "--x-initial", "fast", "--timescale", "1ns/1ps"]
    log = build / "build.log"
    try:
        with output_to(log):
            runner.build(
                verilog_sources=cfg["sources"], includes=cfg["includes"], hdl_toplevel=ports.WRAPPER,
                build_dir=str(build), build_args=args, always=True,
            )
    except SystemExit:
        raise UsageError(f"the design does not build under {sim} (log: {log}):\n{tail(log)}") from None
    log = build / "sim.log"
    try:
        with output_to(log):
            runner.test(
                test_module="tmc429.cocotb.bench",
                hdl_toplevel=ports.WRAPPER,
                build_dir=str(build),
                extra_env={"TMC429_COCOTB_CONFIG": str(build / "config.json")},
            )
    except SystemExit:
        pass  # the result file says what happened
    if not result.is_file():
        raise UsageError(f"the simulation ended without a result (log: {log}):\n{tail(log)}")
    return json.loads(result.read_text())


def summary(cfg: dict, r: dict, coverage: bool) -> str:
    hit = sum(1 for v in r["coverage"].values() if v)
    lines = [
        f"cocotb {cfg['label']} ({cfg['variant']}, profile {cfg['profile']}): seed {cfg['seed']}",
        f"cycles:       {r['cycles']}",
        f"transactions: {r['frames']} SPI frames, {r['pin_changes']} pin changes",
        f"mismatches:   {0 if r['mismatch_cycle'] is None and not r['xz'] else 1}",
        f"coverage:     {hit} of {len(r['coverage'])} bins hit",
        f"speed:        {r['cycles'] / r['seconds']:.0f} CLK cycles/s" if r["seconds"] > 0 else "speed:        -",
    ]
    if cfg["absent"]:
        lines.append(f"not compared: {', '.join(cfg['absent'])} (absent in the design)")
    out = "\n".join(lines) + "\n"
    if r["xz"]:
        out += f"MISMATCH at cycle {r['xz']['cycle']} ({cfg['label']}, seed {cfg['seed']}): X or Z on {r['xz']['pins']}\n"
    if r["report"]:
        out += r["report"]
    if coverage:
        out += r["coverage_table"]
    return out


def main(argv: Optional[Sequence[str]] = None) -> int:
    a = parse_args(argv)
    try:
        cfg = prepare(a)
        r = simulate(a.sim, cfg)
    except UsageError as e:
        print(f"tmc429.cocotb: error: {e}", file=sys.stderr)
        return 2
    print(summary(cfg, r, a.coverage), end="")
    return 1 if (r["mismatch_cycle"] is not None or r["xz"]) else 0


