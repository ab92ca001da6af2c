#!/usr/bin/env python3
"""Vector files read back: a mutation fuzzer of the replay player (vectors/tb/vec_player.vh), the
parser that reads .hex, .cols and .meta files in a user's simulator. It is Verilog, so libFuzzer
cannot drive it: this harness mutates the golden set spi-datasheet-tmc429 (bytes replaced,
inserted, deleted; lines dropped, doubled, swapped; the file cut; `@address` and `//` lines, X and
Z digits) and replays each mutant under Icarus Verilog.

Rules: the player always ends with `N passed, N failed` and never crashes or hangs (20 s); a clean
pass means the .hex holds, as $readmemh reads it (words between whitespace and comments), exactly
`cycles` well-framed lines: each of the line width in hex digits, sentinel digit A, the XOR of
its digits 0, no X or Z, no `@address`. (Lines dropped, doubled or moved whose framing holds make
another valid vector file: its replay may pass.) A mutant breaking a rule is saved in the
artifacts directory and the harness exits 1.

  fuzz/replay.py --out DIR [--time SECONDS | --runs N] [--seed S]
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import time

GOLDEN = "vectors/golden/spi-datasheet-tmc429"
SUMMARY = re.compile(r"^(\d+) passed, (\d+) failed$")


def build(work):
    meta = open(GOLDEN + ".meta").read()
    chip = re.search(r"^chip_code (\d+)$", meta, re.M).group(1)
    vvp = os.path.join(work, "tb.vvp")
    subprocess.run(["iverilog", "-g2005", "-P", f"tb_spi.CHIP={chip}", "-I", "vectors/tb", "-o", vvp,
                    "vectors/tb/tb_spi.v", "rtl/tmc429_spi_slave.v", "rtl/tmc429_sync.v"], check=True)
    width = int(re.search(r"^width (\d+)$", meta, re.M).group(1))
    return vvp, int(re.search(r"^cycles (\d+)$", meta, re.M).group(1)), width // 4


def well_framed(hexfile, cycles, digits):
    """Whether the file is `cycles` well-framed lines of `digits` hex digits, as $readmemh reads it."""
    text = re.sub(rb"/\*.*?\*/", b" ", hexfile, flags=re.S)
    text = re.sub(rb"//[^\n]*", b" ", text)
    words = text.split()
    if len(words) != cycles:
        return False
    for w in words:
        if len(w) != digits or w[:1] not in (b"a", b"A") or not re.fullmatch(rb"[0-9a-fA-F]+", w):
            return False
        x = 0
        for c in w:
            x ^= int(chr(c), 16)
        if x:
            return False
    return True


def mutate(rng, data):
    b = bytearray(data)
    for _ in range(rng.randint(1, 3)):
        lines = bytes(b).split(b"\n")
        op = rng.randrange(9)
        pos = rng.randrange(len(b) + 1)
        char = rng.choice(b"0123456789ABCDEFabcdefxXzZ_@/ \t\r\n") if rng.random() < 0.8 else rng.randrange(256)
        if op == 0 and b:
            b[min(pos, len(b) - 1)] = char
        elif op == 1:
            b.insert(pos, char)
        elif op == 2 and b:
            del b[pos:pos + rng.randint(1, 8)]
        elif op == 3:
            del lines[rng.randrange(len(lines))]
            b = bytearray(b"\n".join(lines))
        elif op == 4:
            i = rng.randrange(len(lines))
            lines.insert(i, lines[i])
            b = bytearray(b"\n".join(lines))
        elif op == 5 and len(lines) > 1:
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
            b = bytearray(b"\n".join(lines))
        elif op == 6:
            b = b[:pos]
        elif op == 7:
            lines.insert(rng.randrange(len(lines) + 1), b"@%x" % rng.randrange(2048))
            b = bytearray(b"\n".join(lines))
        else:
            lines.insert(rng.randrange(len(lines) + 1), b"// " + bytes(rng.choice(lines)))
            b = bytearray(b"\n".join(lines))
    return bytes(b)


def replay(vvp, d):
    stem = os.path.join(d, "m")
    try:
        r = subprocess.run(["vvp", "-n", vvp, f"+hex={stem}.hex", f"+cols={stem}.cols", f"+meta={stem}.meta"],
                           capture_output=True, timeout=20)
    except subprocess.TimeoutExpired:
        return None, "hang (20 s)"
    out = [l for l in r.stdout.decode("latin-1").splitlines() if not l.startswith("- ") and "$finish" not in l]
    last = out[-1] if out else ""
    if r.returncode != 0:
        return last, f"exit {r.returncode}"
    if not SUMMARY.match(last):
        return last, "no 'N passed, N failed' line"
    return last, None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--time", type=float)
    ap.add_argument("--runs", type=int)
    ap.add_argument("--seed", type=int, default=int(time.time()))
    a = ap.parse_args()
    work = os.path.join(a.out, f"replay-{os.getpid()}")
    art = os.path.join(a.out, "artifacts", "replay")
    os.makedirs(work, exist_ok=True)
    os.makedirs(art, exist_ok=True)
    rng = random.Random(a.seed)
    golden = {e: open(f"{GOLDEN}.{e}", "rb").read() for e in ("hex", "cols", "meta")}
    try:
        vvp, cycles, digits = build(work)
        clean = f"{cycles} passed, 0 failed"
        start, runs, passes = time.time(), 0, 0
        while (a.runs is None or runs < a.runs) and (a.time is None or time.time() - start < a.time):
            which = "hex" if rng.random() < 0.8 else rng.choice(["cols", "meta"])
            files = dict(golden)
            files[which] = mutate(rng, golden[which])
            for e, b in files.items():
                open(os.path.join(work, f"m.{e}"), "wb").write(b)
            last, bad = replay(vvp, work)
            runs += 1
            if bad is None and which == "hex" and last == clean and not well_framed(files["hex"], cycles, digits):
                bad = "a .hex that is not well framed replayed as a clean pass"
            if last == clean:
                passes += 1
            if bad:
                dst = os.path.join(art, f"finding-{runs}")
                os.makedirs(dst, exist_ok=True)
                for e in ("hex", "cols", "meta"):
                    shutil.copy(os.path.join(work, f"m.{e}"), os.path.join(dst, f"m.{e}"))
                print(f"replay: FINDING after {runs} executions: {bad} (last line {last!r}); mutant in {dst}",
                      file=sys.stderr)
                return 1
        print(f"fuzz: replay: {runs} executions in {time.time() - start:.0f} s (seed {a.seed}), "
              f"{passes} mutants replayed as a clean pass (all well framed), 0 findings")
        return 0
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
