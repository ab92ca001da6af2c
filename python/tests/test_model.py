"""The chip at pin level, the virtual µC and the register map (values from the datasheets and
docs/model-contract.md)."""

import pytest

import tmc429


def test_reset_pins_follow_c2():
    for v in tmc429.VARIANTS:
        chip = tmc429.Chip(v)
        o = chip.outputs
        assert (o.nint_sdo_c, o.sdoz_c_oe, o.nscs_s, o.nscs2, o.nscs3) == (True, False, True, True, True)
        assert o.poscmp == (v == "tmc429")  # C2: x_actual 0 matches pos_comp 0 (C65); C90: only the TMC429 has the pin
        assert chip.cycle == 0 and chip.fclk == (16_000_000 if v == "tmc428" else 32_000_000)


def test_words_and_pins_agree():
    assert tmc429.INPUT_PINS[0] == "nscs_c" and tmc429.OUTPUT_PINS[10] == "poscmp"
    assert tmc429.Inputs().word == 0x383  # idle bus, REFR pulled up
    assert tmc429.Inputs(ref2=True).word == 0x383 | 1 << 5
    assert tmc429.Inputs.from_word(0x383) == tmc429.Inputs()
    a, b = tmc429.Chip("tmc429"), tmc429.Chip("tmc429")
    for w in [0x383, 0x382, 0x380, 0x381, 0x383] * 20:
        assert a.tick(tmc429.Inputs.from_word(w)).word == b.tick_word(w)
    with pytest.raises(TypeError, match="unknown pin 'ref4'"):
        tmc429.Inputs(ref4=True)


def test_type_version_and_datasheet_read():
    # TMC429 §8.2.4.4: type_version $429101.
    chip = tmc429.Chip("tmc4210")
    assert chip.peek("type_version") == 0x429101
    host = tmc429.Host("tmc429")
    assert host.read("type_version") == 0x429101
    # [428] §6.5: write dx_ref_tolerance $123 to motor 0, read it back.
    host.write("dx_ref_tolerance", 0x123, motor=0)
    assert host.read("dx_ref_tolerance", motor=0) == 0x123
    assert host.read_fields("pmul_pdiv", motor=0)["pmul"] == 0x80  # C22: bit 15 reads 1


def test_fields_keep_the_others_and_signed_fields_read_signed():
    host = tmc429.Host("tmc429")
    host.write("ref_conf_rm", motor=1, rm=2, soft_stop=1)
    host.write("rm", 3, motor=1)
    assert host.read_fields("ref_conf_rm", motor=1) == {
        "lp": 0, "ref_rnl": 0, "soft_stop": 1, "disable_stop_r": 0, "disable_stop_l": 0, "rm": 3}
    host.write("x_target", -300, motor=2)
    assert host.read("x_target", motor=2) == -300
    assert host.peek("x_target", motor=2) == -300


def test_a_ramp_move_arrives():
    host = tmc429.Host("tmc429")
    host.write("clk_config", motor=0, pulse_div=3, ramp_div=3)
    host.write("v_min", 1, motor=0)
    host.write("v_max", 2047, motor=0)
    host.write("a_max", 1000, motor=0)
    host.write("pmul_pdiv", motor=0, pmul=247, pdiv=2)
    host.write("x_target", 1000, motor=0)
    host.wait_for_target(0, timeout=0.2)
    assert host.read("x_actual", motor=0) == 1000
    assert host.probes.motor[0].v_internal == 0
    with pytest.raises(TimeoutError, match="motor 0 at its target"):
        host.write("x_target", 0, motor=0)
        host.wait_for_target(0, timeout=1e-5)


def test_bad_names_and_values_say_what_was_expected():
    host = tmc429.Host("tmc429")
    with pytest.raises(ValueError, match="unknown register or field 'v_maks': expected one of x_target"):
        host.write("v_maks", 3, motor=0)
    with pytest.raises(ValueError, match="'x_target' is a motor register or field: give motor=0..2"):
        host.write("x_target", 1)
    with pytest.raises(ValueError, match=r"v_max.v_max = 4096 out of range: expected 0..2047 \(11 bits\)"):
        host.write("v_max", 4096, motor=0)
    with pytest.raises(ValueError, match="a_actual is read-only"):
        host.write("a_actual", 1, motor=0)
    with pytest.raises(ValueError, match="'global_parameters' is a global register or field: leave motor out"):
        host.write("global_parameters", 0, motor=0)
    with pytest.raises(ValueError, match="motor=1: the tmc4210 has motors 0..0"):
        tmc429.Host("tmc4210").read("x_actual", motor=1)
    with pytest.raises(ValueError, match="fclk=40000000: the tmc429 runs at 32 MHz at most"):
        tmc429.Chip("tmc429", fclk=40_000_000)
    with pytest.raises(ValueError, match="unknown chip 'tmc430'"):
        tmc429.Chip("tmc430")
    with pytest.raises(ValueError, match="below the minimum of 3 CLK"):
        tmc429.Host(sck_half=2)


def test_register_map():
    regs = {r.name: r for r in tmc429.registers("tmc429")}
    assert regs["x_target"].addresses == [0x00, 0x10, 0x20]
    assert regs["global_parameters"].addresses == [0x3F]
    assert len(regs["ram_microstep_table"].addresses) == 32
    f = {x.name: x for x in regs["ref_conf_rm"].fields}
    assert (f["rm"].lsb, f["rm"].width, f["rm"].access) == (0, 2, "RW")
    assert [r.name for r in tmc429.registers("tmc4210")].count("current_scaling") == 0
