#!/usr/bin/env python3
"""Checks that GTKWave's evcd2vcd output of a `tmc429 vectors --format evcd` file equals the
pin VCD of the same set (`--format vcd`), docs/vectors.md "EVCD and pin VCD".

Usage: evcd_equal.py CONVERTED.vcd PINS.vcd

evcd2vcd splits each port P into P_I (the level the test fixture drives) and P_O (the level
the chip drives), `z` when that side does not drive. The pin's level is the side that drives
(`z` when neither does); both sides driving at once is an error. Every pin's sequence of
(time, level) changes must equal the pin VCD's, and so must the pins and the timescale.
Prints `N pins, M changes equal` and exits 0, or the first differences and exits 1.
"""
import sys


def fail(msg):
    print(f"evcd_equal: {msg}", file=sys.stderr)
    sys.exit(1)


def parse(path):
    """(timescale, {name: [(time, value)]}) of a VCD of scalar variables."""
    ids, changes, t, timescale = {}, {}, 0, None
    with open(path) as f:
        lines = iter(f)
        for line in lines:
            w = line.split()
            if not w:
                continue
            if w[0] == "$timescale":
                text = w[1:]
                while "$end" not in text:
                    text += next(lines).split()
                timescale = "".join(text[: text.index("$end")])
            elif w[0] == "$var":
                code, name = w[3], w[4]
                ids.setdefault(code, []).append(name)
                changes[name] = []
            elif w[0][0] == "#":
                t = int(w[0][1:])
            elif w[0][0] in "01xzXZ" and len(w) == 1:
                for name in ids.get(w[0][1:], []):
                    changes[name].append((t, w[0][0].lower()))
    return timescale, changes


def settle(seq):
    """The last value at each time, then consecutive equal values merged."""
    out = []
    for t, v in seq:
        if out and out[-1][0] == t:
            out[-1] = (t, v)
        else:
            out.append((t, v))
    merged = []
    for t, v in out:
        if not merged or merged[-1][1] != v:
            merged.append((t, v))
    return merged


def resolve(name, i_seq, o_seq):
    """The pin level from the fixture side and the chip side."""
    events = sorted([(t, 0, v) for t, v in settle(i_seq)] + [(t, 1, v) for t, v in settle(o_seq)])
    side, out = ["z", "z"], []
    k = 0
    while k < len(events):
        t = events[k][0]
        while k < len(events) and events[k][0] == t:
            side[events[k][1]] = events[k][2]
            k += 1
        if side[0] != "z" and side[1] != "z":
            fail(f"{name} at {t}: the fixture drives {side[0]} and the chip drives {side[1]}")
        out.append((t, side[1] if side[1] != "z" else side[0]))
    return settle(out)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    conv_ts, conv = parse(sys.argv[1])
    ours_ts, ours = parse(sys.argv[2])
    if conv_ts != ours_ts:
        fail(f"timescale {conv_ts} (converted) vs {ours_ts} (pin VCD)")
    pins = {}
    for name in conv:
        if name[-2:] not in ("_I", "_O"):
            fail(f"{sys.argv[1]}: variable {name} is neither a fixture (_I) nor a chip (_O) side")
        pins.setdefault(name[:-2], None)
    if sorted(pins) != sorted(ours):
        fail(f"pins {sorted(pins)} (converted) vs {sorted(ours)} (pin VCD)")
    n = 0
    for p in ours:
        got, want = resolve(p, conv.get(p + "_I", []), conv.get(p + "_O", [])), settle(ours[p])
        if got != want:
            diff = next(k for k in range(min(len(got), len(want)) + 1) if k >= min(len(got), len(want)) or got[k] != want[k])
            fail(f"pin {p}: change {diff}: converted {got[diff:diff + 3]} vs pin VCD {want[diff:diff + 3]} "
                 f"({len(got)} and {len(want)} changes)")
        n += len(want)
    print(f"{sys.argv[1]}: {len(ours)} pins, {n} changes equal {sys.argv[2]}")


if __name__ == "__main__":
    main()
