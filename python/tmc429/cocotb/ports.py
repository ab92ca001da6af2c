"""The design's ports, the port map and the wrapper that connects the pins to them.

The harness needs the design's port list (name, direction, width) before it builds anything:
it asks the simulator's own front end, which is also the first check that the design compiles
(Icarus: ``iverilog -s TOP`` writes the ports as ``.port_info`` lines of the root scope;
Verilator: ``verilator --xml-only``). The port map (``--port-map FILE``) names the port of each
pin where it is not the pin's own name; the wrapper module ``tmc429_cocotb_top`` then packs the
inputs and outputs into one word each (bit k = ``INPUT_PINS[k]`` / ``OUTPUT_PINS[k]``), so that
one write and one read per CLK edge drive and sample every pin.
"""

from __future__ import annotations

import re
import subprocess
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Tuple

from .. import INPUT_PINS, OUTPUT_PINS

WRAPPER = "tmc429_cocotb_top"
#: The pins besides INPUT_PINS and OUTPUT_PINS: the clock and the synchronous reset (C2).
CONTROL_PINS = ("clk", "rst")
#: Tri-state pairs: the data and its enable are there together or not at all.
PAIRS = (("sdoz_c", "sdoz_c_oe"), ("sdi_s_o", "sdi_s_oe"))


class UsageError(Exception):
    """Bad input: the command exits 2 with this message."""


@dataclass(frozen=True)
class Port:
    name: str
    direction: str  # "input", "output" or "inout"
    width: int


@dataclass(frozen=True)
class Design:
    """A top module as the simulator elaborated it."""

    ports: Tuple[Port, ...]
    #: Its parameters (not localparams), by name.
    parameters: Tuple[str, ...]


@dataclass
class Connection:
    """Where a pin goes: a port (``inverted`` for an active-low port), or nowhere (``port`` None)."""

    pin: str
    port: Optional[str]
    inverted: bool = False
    origin: str = "by name"


@dataclass
class PortMap:
    pins: Dict[str, Connection] = field(default_factory=dict)
    #: Design inputs no pin drives, tied to a constant: ``tie PORT = VALUE``.
    ties: Dict[str, str] = field(default_factory=dict)


def parse_port_map(path: Path) -> PortMap:
    """Reads a port map: one ``PIN = PORT`` per line (``PIN = ~PORT`` for a port of the other
    polarity, ``PIN = -`` for a pin the design does not have), ``tie PORT = VALUE`` for a design
    input no pin drives; ``#`` starts a comment."""
    try:
        text = path.read_text()
    except OSError as e:
        raise UsageError(f"--port-map {path}: cannot read: {e.strerror}") from None
    pins = list(CONTROL_PINS) + list(INPUT_PINS) + list(OUTPUT_PINS)
    m = PortMap()
    for n, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        where = f"{path}:{n}"
        tie = re.fullmatch(r"tie\s+([A-Za-z_][\w$]*)\s*=\s*(\S+)", line)
        if tie:
            m.ties[tie.group(1)] = tie.group(2)
            continue
        g = re.fullmatch(r"([A-Za-z_]\w*)\s*=\s*(~?)\s*([A-Za-z_][\w$]*|-)", line)
        if not g:
            raise UsageError(f"{where}: expected 'PIN = PORT', 'PIN = ~PORT', 'PIN = -' or 'tie PORT = VALUE', found '{raw.strip()}'")
        pin, inv, port = g.group(1).lower(), g.group(2) == "~", g.group(3)
        if pin not in pins:
            raise UsageError(f"{where}: unknown pin '{g.group(1)}': expected one of {', '.join(pins)}")
        if pin in m.pins:
            raise UsageError(f"{where}: pin '{pin}' mapped twice")
        if port == "-" and (inv or pin in CONTROL_PINS):
            raise UsageError(f"{where}: '{pin}' cannot be absent" if pin in CONTROL_PINS else f"{where}: '~-' means nothing")
        m.pins[pin] = Connection(pin, None if port == "-" else port, inv, where)
    return m


def _run(cmd: Sequence[str], what: str) -> subprocess.CompletedProcess:
    try:
        return subprocess.run(list(cmd), capture_output=True, text=True)
    except FileNotFoundError:
        raise UsageError(f"{cmd[0]} not found: {what}") from None


def _first_lines(text: str, n: int = 12) -> str:
    lines = [l for l in text.splitlines() if l.strip()]
    more = f"\n  … ({len(lines) - n} more lines)" if len(lines) > n else ""
    return "\n".join("  " + l for l in lines[:n]) + more


def include_dirs(sources: Sequence[Path]) -> List[Path]:
    """The directories of the sources, where an `include (rtl/tmc429_regmap.vh, rtl/tmc429_schedule.vh) is found."""
    return sorted({s.resolve().parent for s in sources})


def design_icarus(sources: Sequence[Path], top: str, parameters: Dict[str, str], work: Path) -> Design:
    """``top`` as Icarus Verilog elaborates it (with the parameters)."""
    out = work / "ports.vvp"
    cmd = ["iverilog", "-g2012", "-o", str(out), "-s", top]
    cmd += [f"-P{top}.{k}={v}" for k, v in parameters.items()]
    cmd += [f"-I{d}" for d in include_dirs(sources)]
    cmd += [str(s) for s in sources]
    r = _run(cmd, "install Icarus Verilog (Debian: apt-get install iverilog)")
    if r.returncode != 0:
        raise UsageError(f"the design does not compile (iverilog, toplevel {top}):\n{_first_lines(r.stderr + r.stdout)}")
    for k in parameters:
        if re.search(rf"parameter {re.escape(k)} not found", r.stderr):
            raise UsageError(f"--parameter {k}: {top} has no parameter {k}")
    ports: List[Port] = []
    params: List[str] = []
    in_root = False
    for line in out.read_text(errors="replace").splitlines():
        s = re.match(r'S_\S+ \.scope module, "([^"]+)" "([^"]+)"', line)
        if s:
            in_root = s.group(2) == top and ", S_" not in line
            continue
        p = re.match(r'\s*\.port_info \d+ /(INPUT|OUTPUT|INOUT) (\d+) "([^"]+)"', line)
        if p and in_root:
            ports.append(Port(p.group(3), p.group(1).lower(), int(p.group(2))))
        q = re.match(r'P_\S+ \.param/\w+ "([^"]+)" 0 ', line)
        if q and in_root:
            params.append(q.group(1))
    return Design(tuple(ports), tuple(params))


def design_verilator(sources: Sequence[Path], top: str, parameters: Dict[str, str], work: Path) -> Design:
    """``top`` as Verilator elaborates it (with the parameters)."""
    out = work / "ports.xml"
    cmd = ["verilator", "--xml-only", "-Wno-fatal", "--top-module", top, "--xml-output", str(out)]
    cmd += [f"-G{k}={v}" for k, v in parameters.items()]
    cmd += [f"-I{d}" for d in include_dirs(sources)]
    cmd += [str(s) for s in sources]
    r = _run(cmd, "install Verilator 5 (Debian: apt-get install verilator)")
    if r.returncode != 0:
        raise UsageError(f"the design does not compile (verilator, toplevel {top}):\n{_first_lines(r.stderr + r.stdout)}")
    root = ET.parse(out).getroot()
    widths = {}
    for d in root.iter("basicdtype"):
        left, right = d.get("left"), d.get("right")
        widths[d.get("id")] = abs(int(left) - int(right)) + 1 if left is not None else 1
    for mod in root.iter("module"):
        if mod.get("topModule") == "1":
            vs = list(mod.findall("var"))
            return Design(
                tuple(Port(v.get("name"), v.get("dir"), widths.get(v.get("dtype_id"), 0)) for v in vs if v.get("dir") in ("input", "output", "inout")),
                tuple(v.get("name") for v in vs if v.get("param") == "true"),
            )
    raise UsageError(f"the design does not compile (verilator found no toplevel {top})")


def design(sim: str, sources: Sequence[Path], top: str, parameters: Dict[str, str], work: Path) -> Design:
    """``top`` as the front end of ``sim`` ("icarus" or "verilator") elaborates it."""
    find = design_icarus if sim == "icarus" else design_verilator
    return find(sources, top, parameters, work)


def connect(ports: Sequence[Port], port_map: PortMap, top: str) -> Dict[str, Connection]:
    """Each pin's port: from the port map, else the port of the pin's own name. Every port of
    the design must exist, have the pin's direction and 1 bit; every design input must be
    driven by a pin or tied."""
    by_name = {p.name: p for p in ports}
    plist = ", ".join(f"{p.direction} {p.name}" + (f"[{p.width - 1}:0]" if p.width > 1 else "") for p in ports)
    conns: Dict[str, Connection] = {}
    for pin in list(CONTROL_PINS) + list(INPUT_PINS) + list(OUTPUT_PINS):
        c = port_map.pins.get(pin)
        if c is None:
            if pin not in by_name:
                raise UsageError(
                    f"pin '{pin}' has no port: {top} has no port '{pin}' and the port map names none "
                    f"(add '{pin} = PORT' to the port map, or '{pin} = -' if the design lacks the pin); "
                    f"{top}'s ports: {plist}"
                )
            c = Connection(pin, pin)
        if c.port is not None:
            want = "output" if pin in OUTPUT_PINS else "input"
            p = by_name.get(c.port)
            if p is None:
                raise UsageError(f"{c.origin}: '{c.port}' is not a port of {top}; its ports: {plist}")
            if p.direction != want or p.width != 1:
                raise UsageError(f"{c.origin}: pin '{pin}' needs a 1-bit {want}, but {top}'s port '{p.name}' is a {p.width}-bit {p.direction}")
        conns[pin] = c
    for data, oe in PAIRS:
        if (conns[data].port is None) != (conns[oe].port is None):
            raise UsageError(f"the tri-state pin {data} and its enable {oe} go together: map both or mark both absent ('-')")
    used = {c.port for c in conns.values() if c.port}
    for port in port_map.ties:
        if port not in by_name or by_name[port].direction != "input":
            raise UsageError(f"tie {port}: {top} has no input '{port}'; its ports: {plist}")
        if port in used:
            raise UsageError(f"tie {port}: the port is already connected to a pin")
    loose = [p.name for p in ports if p.direction == "input" and p.name not in used and p.name not in port_map.ties]
    if loose:
        raise UsageError(
            f"{top}'s input(s) {', '.join(loose)} are driven by no pin: map them to pins in the port map "
            f"or give them a constant ('tie PORT = VALUE')"
        )
    return conns


def wrapper(top: str, parameters: Dict[str, str], conns: Dict[str, Connection], ties: Dict[str, str]) -> str:
    """The Verilog of the wrapper: the design with its pins packed into ``pins_in``/``pins_out``."""
    ni, no = len(INPUT_PINS), len(OUTPUT_PINS)
    lines = [
        "// Generated by python -m tmc429.cocotb: the design under test with its pins packed into",
        "// one word per direction (bit k = tmc429.INPUT_PINS[k] / OUTPUT_PINS[k]).",
        "`timescale 1ns / 1ps",
        "`default_nettype none",
        f"module {WRAPPER} (",
        "    input  wire clk,",
        "    input  wire rst,",
        f"    input  wire [{ni - 1}:0] pins_in,",
        f"    output wire [{no - 1}:0] pins_out",
        ");",
        f"    wire [{no - 1}:0] o;",
    ]
    conn_lines: List[str] = []
    for pin in CONTROL_PINS:
        c = conns[pin]
        conn_lines.append(f".{c.port}({'~' if c.inverted else ''}{pin})")
    for k, pin in enumerate(INPUT_PINS):
        c = conns[pin]
        if c.port:
            conn_lines.append(f".{c.port}({'~' if c.inverted else ''}pins_in[{k}])")
    for k, pin in enumerate(OUTPUT_PINS):
        c = conns[pin]
        if c.port:
            conn_lines.append(f".{c.port}(o[{k}])")
    for port, value in ties.items():
        conn_lines.append(f".{port}({value})")
    params = ", ".join(f".{k}({v})" for k, v in parameters.items())
    lines.append(f"    {top} {'#(' + params + ') ' if params else ''}dut (")
    lines.append(",\n".join("        " + c for c in conn_lines))
    lines.append("    );")
    for k, pin in enumerate(OUTPUT_PINS):
        c = conns[pin]
        src = "1'b0" if c.port is None else (f"~o[{k}]" if c.inverted else f"o[{k}]")
        lines.append(f"    assign pins_out[{k}] = {src};  // {pin}")
    lines += ["endmodule", "`default_nettype wire", ""]
    return "\n".join(lines)


def absent_outputs(conns: Dict[str, Connection]) -> Tuple[str, ...]:
    return tuple(pin for pin in OUTPUT_PINS if conns[pin].port is None)
