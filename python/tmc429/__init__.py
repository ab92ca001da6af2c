"""The bit-exact golden model of the Trinamic TMC428 / TMC429 / TMC4210 motion controllers.

- :class:`Chip`: the chip at pin level, one call per rising CLK edge (contract C1);
- :class:`Host`: the virtual microcontroller, register and field writes and reads by name over
  the SPI pins, switch inputs and waits;
- :func:`registers`: the register map;
- :func:`run_scenario`, :func:`export_vectors`: scenario files and test vectors;
- :class:`Stimulus`, :class:`Reference`: the seeded stimulus of ``tmc429 cosim`` and the model
  driven by it, the reference a design under test is compared with;
- :mod:`tmc429.cocotb`: the cocotb harness, ``python -m tmc429.cocotb``.

docs/verify-your-rtl.md in the repository shows the routes from install to a first mismatch.
"""

from ._native import (
    INPUT_PINS,
    OUTPUT_PINS,
    PROFILES,
    VARIANTS,
    ChainProbe,
    Chip,
    Field,
    Host,
    Inputs,
    MotorProbe,
    Outputs,
    Probes,
    Reference,
    Register,
    ScenarioReport,
    Stimulus,
    Transaction,
    export_vectors,
    registers,
    run_scenario,
)

__all__ = [
    "INPUT_PINS",
    "OUTPUT_PINS",
    "PROFILES",
    "VARIANTS",
    "ChainProbe",
    "Chip",
    "Field",
    "Host",
    "Inputs",
    "MotorProbe",
    "Outputs",
    "Probes",
    "Reference",
    "Register",
    "ScenarioReport",
    "Stimulus",
    "Transaction",
    "export_vectors",
    "registers",
    "run_scenario",
]
