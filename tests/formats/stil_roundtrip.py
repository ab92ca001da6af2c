#!/usr/bin/env python3
"""Reads a STIL file of `tmc429 vectors --format stil` with an independent STIL parser
(Semi_ATE.STIL from PyPI, its dump compiler) and checks that its vectors round-trip to the
pin-level vectors (.hex/.cols/.meta) of the same set (docs/vectors.md, "STIL").

Usage: stil_roundtrip.py FILE.stil STEM     (STEM.hex, STEM.cols, STEM.meta)

Every waveform character is interpreted through the waveform the parser reports for it
(timing.txt of the dump compiler: drive events D/U, compare events L/H/T), never by its
letter, and the timing is checked against the .meta's fclk: period 10^12/fclk ps, CLK down at
0 and up at the half period, inputs driven at 0, outputs strobed after the CLK edge. The pins
map to the columns as docs/vectors.md says: a pin P with a column P_oe is a tri-state output
(data P while P_oe = 1, else high impedance); the input P with columns P_o and P_oe is
bidirectional (the tester drives P while P_oe was and is 0, the chip drives P_o while P_oe).
Prints `N vectors equal` and exits 0, or the first differences and exits 1.
"""
import contextlib
import io
import os
import sys
import tempfile

from Semi_ATE.STIL.parsers.STILDumpCompiler import STILDumpCompiler


def fail(msg):
    print(f"stil_roundtrip: {msg}", file=sys.stderr)
    sys.exit(1)


def read_meta(stem):
    meta = {}
    with open(stem + ".meta") as f:
        for line in f:
            p = line.split(None, 1)
            if len(p) == 2 and not p[0].startswith("#"):
                meta.setdefault(p[0], p[1].strip())
    cols = []
    with open(stem + ".cols") as f:
        for line in f:
            name, width, d = line.split()
            cols.append((name, int(width), d))
    return meta, cols


def read_hex(stem, cols):
    """Yields one dict column -> value per line of STEM.hex."""
    total = sum(w for _, w, _ in cols)
    with open(stem + ".hex") as f:
        for line in f:
            word = int(line, 16)
            v, lo = {}, total
            for name, w, _ in cols:
                lo -= w
                v[name] = (word >> lo) & ((1 << w) - 1)
            yield v


def compile_stil(path, out):
    """Runs the parser's dump compiler; returns (signal order, [wfc string per vector],
    {(signal, wfc): [(event, time_fs)]})."""
    log = io.StringIO()
    with contextlib.redirect_stdout(log):
        c = STILDumpCompiler(path, out_folder=out, expanding_procs=True)
        c.compile()
    if c.err_line != -1:
        fail(f"{path}: the STIL parser reports an error at line {c.err_line}, column {c.err_col}: {c.err_msg}\n{log.getvalue()}")
    waves = {}
    with open(os.path.join(out, "timing.txt")) as f:
        for line in f:
            if line.startswith("#"):
                continue
            p = [x.strip() for x in line.split("|")]
            sig, wfc = p[2], p[3]
            ev = []
            for e in p[4:]:
                if e:
                    kind, t = e.split(":")
                    ev.append((kind, int(t[:-2])))
            waves[(sig, wfc)] = ev
    blocks = [n for n in os.listdir(out) if n.endswith(".pattern_block")]
    if len(blocks) != 1:
        fail(f"{path}: expected one pattern block, the parser made {blocks}")
    order, vecs = None, []
    with open(os.path.join(out, blocks[0])) as f:
        for line in f:
            if line.startswith("# SIGNALS_ORDER|"):
                order = line.split("|")[1].split("+")
            elif line[:1] != "#" and "|VECTOR|" in line:
                vecs.append(line.split("|")[3].strip())
    if order is None:
        fail(f"{path}: the parser's dump has no signal order")
    return order, vecs, waves


def meaning(waves, sig, wfc, period_fs, rise_fs):
    """('clock'|'drive'|'expect'|'off'|'mask', level) of a waveform character."""
    ev = waves.get((sig, wfc))
    if ev is None:
        fail(f"signal {sig}: waveform character {wfc} has no waveform")
    kinds = [k for k, _ in ev]
    if kinds == ["D", "U"]:
        if ev[0][1] != 0 or ev[1][1] != rise_fs:
            fail(f"{sig} {wfc}: CLK at {ev}, expected down at 0 and up at {rise_fs} fs")
        return ("clock", None)
    if kinds in (["D"], ["U"]):
        if ev[0][1] != 0:
            fail(f"{sig} {wfc}: driven at {ev[0][1]} fs, expected 0")
        return ("drive", int(kinds[0] == "U"))
    compare = [e for e in ev if e[0] in "LHTX"]
    if len(compare) != 1 or not rise_fs < compare[0][1] < period_fs:
        fail(f"{sig} {wfc}: {ev}: expected one compare after the CLK edge ({rise_fs} fs) within the period")
    k = compare[0][0]
    return {"L": ("expect", 0), "H": ("expect", 1), "T": ("off", None), "X": ("mask", None)}[k]


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    path, stem = sys.argv[1], sys.argv[2]
    meta, cols = read_meta(stem)
    names = {n for n, _, _ in cols}
    period_ps = 10**12 // int(meta["fclk"])
    period_fs, rise_fs = period_ps * 1000, period_ps // 2 * 1000
    with tempfile.TemporaryDirectory() as out:
        order, vecs, waves = compile_stil(path, out)
    if len(vecs) != int(meta["cycles"]):
        fail(f"{path}: {len(vecs)} vectors, {stem}.meta says cycles {meta['cycles']}")
    # the pins and the columns each covers
    covered = set()
    for sig in order:
        covered |= {c for c in (sig, sig + "_o", sig + "_oe") if c in names}
    missing = names - covered - {"_sentinel", "_check"}
    if missing:
        fail(f"{path}: no signal carries the columns {sorted(missing)}")
    cache, errors, prev = {}, [], {}
    for k, (wfcs, v) in enumerate(zip(vecs, read_hex(stem, cols))):
        if len(wfcs) != len(order):
            fail(f"{path}: vector {k} has {len(wfcs)} characters for {len(order)} signals")
        for sig, ch in zip(order, wfcs):
            m = cache.get((sig, ch))
            if m is None:
                m = cache[(sig, ch)] = meaning(waves, sig, ch, period_fs, rise_fs)
            what, level = m
            oe = v.get(sig + "_oe")
            bidir = sig + "_o" in names
            if what == "clock":
                ok = sig not in names
            elif what == "drive":
                ok = v.get(sig) == level and (not bidir or (oe == 0 and prev.get(sig, 0) == 0))
            elif what == "expect":
                data = v.get(sig + "_o") if bidir else v.get(sig)
                ok = data == level and oe in (None, 1)
            elif what == "off":
                ok = oe == 0 and (not bidir or prev.get(sig) == 1)
            else:
                ok = False  # the sets compare every pin: no mask
            if not ok:
                errors.append(f"vector {k} signal {sig}: {ch} ({what} {level}) but the .hex line has "
                              + ", ".join(f"{c}={v[c]}" for c in (sig, sig + "_o", sig + "_oe") if c in v))
            if oe is not None:
                prev[sig] = oe
        if len(errors) >= 10:
            break
    if errors:
        fail(f"{path} differs from {stem}.hex:\n  " + "\n  ".join(errors))
    print(f"{path}: {len(vecs)} vectors equal {stem}.hex")


if __name__ == "__main__":
    main()
