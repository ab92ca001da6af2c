"""Scenario files and vectors from Python, as tmc429 run and tmc429 vectors make them."""

import pytest

import tmc429


def test_scenario_file_runs_with_its_expectations(root, tmp_path):
    r = tmc429.run_scenario(root / "examples/scenarios/ramp-move.toml", vcd=tmp_path / "r.vcd", vectors=tmp_path / "v")
    assert r.ok and r.variant == "tmc429" and r.cycles > 0
    assert all(e["passed"] for e in r.expectations) and r.expectations
    assert r.summary.startswith("scenario ")
    assert (tmp_path / "r.vcd").stat().st_size > 0
    assert any(str(f).endswith(".hex") for f in r.files)


def test_scenario_errors_name_file_and_line(tmp_path):
    bad = tmp_path / "typo.toml"
    bad.write_text('chip = "tmc429"\nduration = "1 ms"\n[[write]]\nmotor = 0\nv_maks = 3\n')
    with pytest.raises(ValueError, match="typo.toml:5"):
        tmc429.run_scenario(bad)


def test_export_vectors_of_a_builtin_scenario(tmp_path):
    files = tmc429.export_vectors("chip-hold", tmp_path, unit="chip", format="pins")
    assert sorted(f.suffix for f in files) == [".cols", ".hex", ".meta"]
    with pytest.raises(ValueError, match="unknown unit 'cpu'"):
        tmc429.export_vectors("chip-hold", tmp_path, unit="cpu")
