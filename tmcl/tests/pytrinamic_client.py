#!/usr/bin/env python3
"""Drives `tmc429 tmcl serve` with PyTrinamic's own module classes and checks every answer:
TMCM3110 against `--module tmcm-3110`, TMCM1311 against `--module tmcm-1311`.

Usage: pytrinamic_client.py tcp HOST:PORT | pty /dev/pts/N  [tmcm-3110 | tmcm-1311]
The server must have been started with --analog 0=302 --input 1=0 (values checked below);
for the TMCM-1311 also with --home-switch 0=1000:1200 and --left-switch 0=-3000.
Exit status 0 when every check passed, 1 otherwise.
"""
import sys
import time

from pytrinamic.connections import ConnectionManager
from pytrinamic.modules import TMCM1311, TMCM3110
from pytrinamic.tmcl import TMCLReplyStatusError

failures = []


def check(what, got, want):
    if got != want:
        failures.append(f"{what}: got {got!r}, expected {want!r}")
        print(f"FAIL {what}: got {got!r}, expected {want!r}")
    else:
        print(f"ok   {what} = {got!r}")


def wait_reached(motor, timeout=20.0):
    """Position reached and at rest (a pass through the target while braking is not the end)."""
    t0 = time.time()
    while not (motor.get_position_reached() and motor.get_actual_velocity() == 0):
        if time.time() - t0 > timeout:
            return False
        time.sleep(0.01)
    return True


def status_of(f, *args):
    """The reply status of a call that PyTrinamic raises on (100 when it does not raise)."""
    try:
        f(*args)
        return 100
    except TMCLReplyStatusError as e:
        return e.status_code


def wait_until(f, timeout=20.0):
    t0 = time.time()
    while not f():
        if time.time() - t0 > timeout:
            return False
        time.sleep(0.01)
    return True


def tmcm1311(iface):
    """PyTrinamic's TMCM1311 class on the TMCM-1311 personality: pps, 32-bit positions,
    encoder, drive settings, the closed-loop and stallGuard2 values refused with status 4."""
    m = TMCM1311(iface)
    mot = m.motors[0]
    AP = mot.AP
    check("version string", iface.get_version_string(), "1311V100")
    check("binary version", iface.send(136, 1, 0, 0).value, (1311 << 16) | 0x0100)
    # Ramp in pps and pps² (LinearRampModule), drive settings (DriveSettingModule).
    mot.linear_ramp.max_acceleration = 100000
    mot.linear_ramp.max_velocity = 40000
    check("AP4 max velocity [pps]", mot.linear_ramp.max_velocity, 40000)
    check("AP5 max acceleration [pps/s]", mot.linear_ramp.max_acceleration, 100000)
    mot.drive_settings.max_current = 200
    mot.drive_settings.standby_current = 20
    mot.drive_settings.boost_current = 0
    mot.drive_settings.microstep_resolution = mot.ENUM.MicrostepResolution256Microsteps
    check("AP6 max current", mot.drive_settings.max_current, 200)
    check("AP7 standby current", mot.drive_settings.standby_current, 20)
    check("AP140 microstep resolution", mot.drive_settings.microstep_resolution, 8)
    check("AP15 maximum possible current [mA]", mot.get_axis_parameter(AP.MaximumPossibleCurrent), 2353)
    # Moves: absolute, relative, position reached; 32-bit positions past the TMC429's 24 bits.
    m.move_to(0, 30000)
    check("MVP ABS reached", wait_reached(mot), True)
    check("actual position", mot.actual_position, 30000)
    m.move_by(0, -4400)
    check("MVP REL reached", wait_reached(mot), True)
    check("actual position after MVP REL", mot.get_actual_position(), 25600)
    # Encoder at 4000 positions per revolution (51 200 µsteps), set to the position's count.
    mot.set_axis_parameter(AP.EncoderResolution, 4000)
    mot.set_axis_parameter(AP.EncoderPosition, 2000)
    check("AP237 position error", mot.get_axis_parameter(AP.CLPositionError, signed=True), 0)
    m.move_by(0, 51200)
    check("one revolution reached", wait_reached(mot), True)
    check("AP209 encoder counter", mot.get_axis_parameter(AP.EncoderPosition, signed=True), 6000)
    check("AP237 position error after the move", mot.get_axis_parameter(AP.CLPositionError, signed=True), 0)
    mot.actual_position = 8_388_000
    m.move_by(0, 2000)
    check("MVP REL across 2^23 reached", wait_reached(mot), True)
    check("32-bit actual position", mot.actual_position, 8_390_000)
    # Velocity mode.
    m.rotate(0, -25000)
    ok = wait_until(lambda: abs(mot.get_actual_velocity() + 25000) < 100)
    check("ROR -25000: runs at about -25000 pps", ok, True)
    check("target velocity as commanded", mot.get_target_velocity(), -25000)
    check("AP128 ramp mode velocity", mot.get_axis_parameter(AP.RampMode), 1)
    m.stop(0)
    check("MST: stopped", wait_until(lambda: mot.get_actual_velocity() == 0), True)
    # Home switch on IN1 (the axis's home switch at 1000..1200).
    check("GIO 1, 0 (home switch on IN1) away from it", m.get_digital_input(m.IO.IN1), 0)
    # Reference search mode 8 from above the home switch.
    mot.set_axis_parameter(AP.ReferenceSearchMode, 8)
    mot.set_axis_parameter(AP.ReferenceSearchSpeed, 20000)
    mot.set_axis_parameter(AP.ReferenceSwitchSpeed, 2000)
    mot.actual_position = 0
    m.move_to(0, 5000)
    check("to 5000", wait_reached(mot), True)
    iface.reference_search(0, 0)
    check("RFS done", wait_until(lambda: iface.reference_search(2, 0) == 0), True)
    check("position 0 at the home switch's upper edge", abs(mot.actual_position) <= 4, True)
    # Closed loop, torque mode, stallGuard2 stop: status 4; their settings are kept.
    check("SAP 129 closed loop on", status_of(mot.set_axis_parameter, AP.ClosedLoopMode, 1), 4)
    check("SAP 128 torque mode", status_of(mot.set_axis_parameter, AP.RampMode, 2), 4)
    check("stallGuard2 stop velocity", status_of(mot.stallguard2.set_stop_velocity, 5000), 4)
    mot.set_axis_parameter(AP.StallGuard2Threshold, 7)
    check("AP174 stallGuard2 threshold kept", mot.get_axis_parameter(AP.StallGuard2Threshold, signed=True), 7)
    check("AP206 load value (no motor model)", status_of(mot.stallguard2.get_load_value), 3)
    # Global parameters, I/O.
    check("GP66 serial address", m.get_global_parameter(m.GP0.serialAddress, 0), 1)
    check("GP69 CAN bit rate (kept)", m.get_global_parameter(m.GP0.CANBitrate, 0), 8)
    m.set_global_parameter(42, 2, -123456)
    check("bank 2 user variable 42", m.get_global_parameter(42, 2, signed=True), -123456)
    m.set_digital_output(m.IO.OUT7)
    check("OUT7", m.get_digital_output(m.IO.OUT7), 1)
    check("GIO 0, 1 analog AIN0", m.get_analog_input(0), 302)
    check("GIO 8, 1 supply voltage [0.1 V]", m.get_analog_input(8), 240)
    check("motor 1 does not exist", status_of(iface.send, 6, 1, 1, 0), 4)


def main():
    kind, where = sys.argv[1], sys.argv[2]
    module = sys.argv[3] if len(sys.argv) > 3 else "tmcm-3110"
    if kind == "tcp":
        args = f"--interface socket_serial_tmcl --port {where}"
    else:
        args = f"--interface serial_tmcl --port {where} --data-rate 115200"
    with ConnectionManager(args).connect() as iface:
        if module == "tmcm-1311":
            tmcm1311(iface)
        else:
            tmcm3110(iface)
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    print("all checks passed")
    return 0


def tmcm3110(iface):
    """PyTrinamic's TMCM3110 class on the TMCM-3110 personality."""
    m = TMCM3110(iface)
    # Firmware version, both forms of command 136.
    check("version string", iface.get_version_string(), "3110V100")
    check("binary version", iface.send(136, 1, 0, 0).value, (3110 << 16) | 0x0100)

    mot = [m.motors[i] for i in range(3)]
    # Axis parameters in TMC429 units.
    mot[0].linear_ramp.max_velocity = 1200
    mot[0].linear_ramp.max_acceleration = 600
    check("AP4 max velocity", mot[0].linear_ramp.max_velocity, 1200)
    check("AP5 max acceleration", mot[0].linear_ramp.max_acceleration, 600)
    mot[0].set_axis_parameter(mot[0].AP.MaxCurrent, 200)
    check("AP6 run current", mot[0].get_axis_parameter(mot[0].AP.MaxCurrent), 200)
    mot[1].set_axis_parameter(mot[1].AP.MinimumSpeed, 5)
    check("AP130 v_min axis 1", mot[1].get_axis_parameter(mot[1].AP.MinimumSpeed), 5)
    mot[0].set_axis_parameter(mot[0].AP.RampDivisor, 6)
    check("AP153 ramp divisor", mot[0].get_axis_parameter(mot[0].AP.RampDivisor), 6)
    check("AP154 pulse divisor (default)", mot[0].get_axis_parameter(mot[0].AP.PulseDivisor), 3)
    # A parameter of hardware the module does not have: status 3 (wrong type).
    try:
        mot[0].get_axis_parameter(mot[0].AP.SG2Threshold)
        check("AP174 stallGuard2 threshold status", 100, 3)
    except TMCLReplyStatusError as e:
        check("AP174 stallGuard2 threshold status", e.status_code, 3)

    # MVP ABS, wait for position reached, actual position.
    m.move_to(0, 12000)
    check("MVP ABS reached", wait_reached(mot[0]), True)
    check("actual position after MVP ABS", mot[0].actual_position, 12000)
    check("target position", mot[0].target_position, 12000)
    # MVP REL.
    m.move_by(0, -5000)
    check("MVP REL reached", wait_reached(mot[0]), True)
    check("actual position after MVP REL", mot[0].get_actual_position(), 7000)
    # Axis 2 independently.
    m.move_to(2, -3000)
    check("axis 2 reached", wait_reached(mot[2]), True)
    check("axis 2 actual position", mot[2].get_axis_parameter(mot[2].AP.ActualPosition, signed=True), -3000)
    check("axis 0 unchanged", mot[0].actual_position, 7000)

    # ROR / ROL / MST.
    m.rotate(1, 300)
    time.sleep(0.3)
    v = mot[1].get_axis_parameter(mot[1].AP.ActualVelocity, signed=True)
    check("ROR: axis 1 runs at +300", v, 300)
    check("ROR: ramp mode velocity", mot[1].get_axis_parameter(mot[1].AP.RampMode), 2)
    p1 = mot[1].get_axis_parameter(mot[1].AP.ActualPosition, signed=True)
    check("ROR: position increases", p1 > 0, True)
    iface.send(2, 0, 1, 300)  # ROL
    time.sleep(0.4)
    v = mot[1].get_axis_parameter(mot[1].AP.ActualVelocity, signed=True)
    check("ROL: axis 1 runs at -300", v, -300)
    m.stop(1)
    time.sleep(0.3)
    check("MST: axis 1 stopped", mot[1].get_axis_parameter(mot[1].AP.ActualVelocity, signed=True), 0)
    check("MST: target speed 0", mot[1].get_axis_parameter(mot[1].AP.TargetVelocity, signed=True), 0)

    # Global parameters: bank 0, user variables (bank 2), interrupt configuration (bank 3).
    check("GP66 serial address", m.get_global_parameter(m.GP0.SerialAddress, 0), 1)
    check("GP76 host address", m.get_global_parameter(m.GP0.SerialHostAddress, 0), 2)
    check("GP128 application status", m.get_global_parameter(m.GP0.ApplicationStatus, 0), 0)
    t1 = m.get_global_parameter(m.GP0.TickTimer, 0)
    time.sleep(0.2)
    t2 = m.get_global_parameter(m.GP0.TickTimer, 0)
    print(f"     tick timer advanced {t2 - t1} ms in 200 ms of wall-clock time")
    # Module time follows wall-clock time, or catches up when the host was too slow.
    check("GP132 tick timer advances", t2 - t1 > 0, True)
    m.set_global_parameter(42, 2, -123456)
    check("bank 2 user variable 42", m.get_global_parameter(42, 2, signed=True), -123456)
    m.set_global_parameter(m.GP3.timer_0, 3, 250)
    check("bank 3 timer 0 period", m.get_global_parameter(m.GP3.timer_0, 3), 250)
    try:
        m.set_global_parameter(m.GP0.CANBitRate, 0, 8)
        check("GP69 CAN bit rate status", 100, 3)
    except TMCLReplyStatusError as e:
        check("GP69 CAN bit rate status (no CAN hardware)", e.status_code, 3)

    # SIO / GIO.
    m.set_digital_output(m.IO.OUT3)
    check("GIO 3, 2 after SIO 3, 2, 1", m.get_digital_output(m.IO.OUT3), 1)
    m.clear_digital_output(m.IO.OUT3)
    check("GIO 3, 2 after SIO 3, 2, 0", m.get_digital_output(m.IO.OUT3), 0)
    check("GIO 0, 1 analog AIN0", m.get_analog_input(m.IO.AIN0), 302)
    check("GIO 1, 0 digital IN1 (driven low)", m.get_digital_input(m.IO.IN1), 0)
    check("GIO 2, 0 digital IN2 (open, pull-up)", m.get_digital_input(m.IO.IN2), 1)
    check("GIO 8, 1 supply voltage [0.1 V]", m.get_analog_input(8), 240)

    # State kept across the whole session.
    check("axis 0 still at 7000", mot[0].actual_position, 7000)


if __name__ == "__main__":
    sys.exit(main())
