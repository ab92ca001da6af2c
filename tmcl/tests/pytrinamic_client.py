#!/usr/bin/env python3
"""Drives `tmc429 tmcl serve` with PyTrinamic's own TMCM3110 module class and checks every answer.

Usage: pytrinamic_client.py tcp HOST:PORT | pty /dev/pts/N
The server must have been started with --analog 0=302 --input 1=0 (values checked below).
Exit status 0 when every check passed, 1 otherwise.
"""
import sys
import time

from pytrinamic.connections import ConnectionManager
from pytrinamic.modules import TMCM3110
from pytrinamic.tmcl import TMCLReplyStatusError

failures = []


def check(what, got, want):
    if got != want:
        failures.append(f"{what}: got {got!r}, expected {want!r}")
        print(f"FAIL {what}: got {got!r}, expected {want!r}")
    else:
        print(f"ok   {what} = {got!r}")


def wait_reached(motor, timeout=20.0):
    t0 = time.time()
    while not motor.get_position_reached():
        if time.time() - t0 > timeout:
            return False
        time.sleep(0.01)
    return True


def main():
    kind, where = sys.argv[1], sys.argv[2]
    if kind == "tcp":
        args = f"--interface socket_serial_tmcl --port {where}"
    else:
        args = f"--interface serial_tmcl --port {where} --data-rate 115200"
    with ConnectionManager(args).connect() as iface:
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
        check("GP132 tick timer advances", 0 < t2 - t1 <= 2000, True)
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
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
