"""python -m tmc429.cocotb: bad input exits 2 and names what was expected (no simulation runs)."""

import subprocess
import sys

import pytest

pytest.importorskip("cocotb")


def harness(root, tmp_path, *args):
    cmd = [sys.executable, "-m", "tmc429.cocotb", "--build-dir", str(tmp_path / "b"), "--sim", "icarus", *args]
    return subprocess.run(cmd, capture_output=True, text=True, cwd=root)


def sources(root):
    return ["--sources", *sorted(str(p) for p in (root / "rtl").glob("*.v"))]


def test_unknown_port_in_the_port_map(root, tmp_path):
    m = tmp_path / "m.map"
    m.write_text("# map\nnscs_c = cs_n\n")
    r = harness(root, tmp_path, *sources(root), "--toplevel", "tmc429_chip", "--port-map", str(m))
    assert r.returncode == 2
    assert f"{m}:2: 'cs_n' is not a port of tmc429_chip; its ports: input clk, input rst" in r.stderr


def test_unknown_pin_and_bad_line(root, tmp_path):
    m = tmp_path / "m.map"
    m.write_text("nscs = cs_n\n")
    r = harness(root, tmp_path, *sources(root), "--toplevel", "tmc429_chip", "--port-map", str(m))
    assert r.returncode == 2 and f"{m}:1: unknown pin 'nscs': expected one of clk, rst, nscs_c" in r.stderr
    m.write_text("nscs_c cs_n\n")
    r = harness(root, tmp_path, *sources(root), "--toplevel", "tmc429_chip", "--port-map", str(m))
    assert r.returncode == 2 and f"{m}:1: expected 'PIN = PORT'" in r.stderr


def test_missing_pin(root, tmp_path):
    # tmc429_top has every pin; a design without sdoz_c_oe is made here
    v = tmp_path / "mini_chip.v"
    v.write_text((root / "rtl/tmc429_chip.v").read_text().replace("module tmc429_chip", "module mini_chip")
                 .replace("    output wire sdoz_c_oe,\n", "")
                 .replace("    assign sdoz_c_oe = POSCMP_ABSENT ? 1'b0 : die_sdoz_c_oe;\n", ""))
    srcs = [str(p) for p in sorted((root / "rtl").glob("*.v"))] + [str(v)]
    r = harness(root, tmp_path, "--sources", *srcs, "--toplevel", "mini_chip")
    assert r.returncode == 2
    assert "pin 'sdoz_c_oe' has no port: mini_chip has no port 'sdoz_c_oe' and the port map names none" in r.stderr
    m = tmp_path / "m.map"
    m.write_text("sdoz_c_oe = -\n")
    r = harness(root, tmp_path, "--sources", *srcs, "--toplevel", "mini_chip", "--port-map", str(m))
    assert r.returncode == 2 and "the tri-state pin sdoz_c and its enable sdoz_c_oe go together" in r.stderr


def test_design_that_does_not_compile(root, tmp_path):
    v = tmp_path / "broken.v"
    v.write_text("module broken(input wire clk);\n  assign = ;\nendmodule\n")
    r = harness(root, tmp_path, "--sources", str(v), "--toplevel", "broken")
    assert r.returncode == 2 and "the design does not compile (iverilog, toplevel broken)" in r.stderr
    r = harness(root, tmp_path, *sources(root), "--toplevel", "no_such_module")
    assert r.returncode == 2 and "the design does not compile" in r.stderr


def test_bad_options(root, tmp_path):
    r = harness(root, tmp_path, *sources(root), "--toplevel", "tmc429_chip", "--parameter", "FOO=1")
    assert r.returncode == 2 and "--parameter FOO: tmc429_chip has no parameter FOO" in r.stderr
    r = harness(root, tmp_path, *sources(root), "--toplevel", "tmc429_chip", "--parameter", "CHIP")
    assert r.returncode == 2 and "expected NAME=VALUE" in r.stderr
    r = harness(root, tmp_path, "--sources", "nope.v", "--toplevel", "x")
    assert r.returncode == 2 and "--sources: nope.v: no such file" in r.stderr
    r = harness(root, tmp_path, *sources(root), "--toplevel", "tmc429_chip", "--cycles", "0")
    assert r.returncode == 2 and "--cycles: expected at least 1" in r.stderr
