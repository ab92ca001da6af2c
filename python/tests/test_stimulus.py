"""A seed means the same stimulus as in tmc429 cosim: the fingerprints recorded by
verif/tests/seeds.rs (the one table), computed here through the Python package."""

import itertools
import re

import tmc429


def fingerprints(root):
    text = (root / "verif/tests/seeds.rs").read_text()
    rows = re.findall(r'\("(\w+)", "([\w-]+)", (\d+), (0x[0-9a-f]+), (\d+)\)', text)
    assert len(rows) == 30
    return [(c, p, int(s), int(h, 16), int(t)) for c, p, s, h, t in rows]


def fingerprint(chip, profile, seed, cycles=100_000):
    """FNV-1a over the input word of each edge, as verif/tests/seeds.rs hashes them."""
    ref = tmc429.Reference(chip, profile, seed)
    h, mask = 0xCBF29CE484222325, (1 << 64) - 1
    for _ in range(cycles):
        h = ((h ^ ref.step()) * 0x100000001B3) & mask
    return h


def test_python_gives_the_recorded_stimulus(root):
    for chip, profile, seed, h, _ in fingerprints(root):
        if seed == 1:
            assert fingerprint(chip, profile, seed) == h, (chip, profile, seed)


def test_stimulus_transactions_are_the_seeds():
    a = [t.datagram for t in itertools.islice(tmc429.Stimulus("tmc429", "full", 7), 200)]
    b = [t.datagram for t in itertools.islice(tmc429.Stimulus("tmc429", "full", 7), 200)]
    c = [t.datagram for t in itertools.islice(tmc429.Stimulus("tmc429", "full", 8), 200)]
    assert a == b and a != c
    t = tmc429.Stimulus("tmc429", "registers", 1).next_transaction()
    # the registers profile starts with rm = HOLD_MODE for motor 1 (datasheet numbering)
    assert (t.kind, t.access) == ("frame", "W ref_conf_rm[1] = $000003")


def test_reference_counts_like_cosim():
    ref = tmc429.Reference("tmc429", "motion", 1)
    ref.run(1_000_000)
    # what `tmc429 cosim --seed 1 --cycles 1000000` prints for the same run comes from the same
    # generators; the test of scripts/test-verify compares the two outputs directly
    assert ref.cycle == 1_000_000 and ref.frames > 0
    assert ref.mismatch_cycle is None and ref.mismatch_report("x") is None
    assert set(ref.missed_bins()) < set(ref.coverage())


def test_reference_reports_a_mismatch_like_cosim():
    ref = tmc429.Reference("tmc429", "registers", 1)
    w = ref.output_word
    for _ in range(3000):
        w = ref.exchange(ref.output_word)
        assert w is not None
    bad = ref.output_word ^ 1 << tmc429.OUTPUT_PINS.index("poscmp")
    assert ref.exchange(bad) is None
    assert ref.mismatch_cycle == 3000
    r = ref.mismatch_report("my_chip")
    assert r.startswith("MISMATCH at cycle 3000 (my_chip, seed 1):\n")
    assert "top.poscmp" in r and "SPI transactions (oldest first):" in r


def test_tristate_data_is_compared_only_while_enabled():
    ref = tmc429.Reference("tmc429", "registers", 1)
    o = ref.outputs
    assert not o.sdoz_c_oe
    assert ref.check(ref.output_word ^ 1 << tmc429.OUTPUT_PINS.index("sdoz_c"))
    ref2 = tmc429.Reference("tmc429", "registers", 1, absent=["poscmp"])
    assert ref2.check(ref2.output_word ^ 1 << tmc429.OUTPUT_PINS.index("poscmp"))
