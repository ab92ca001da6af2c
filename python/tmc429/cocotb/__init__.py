"""The cocotb harness of tmc429: a Verilog design with the TMC429 pins and the golden model in
lock-step, on the seeded stimulus of ``tmc429 cosim``, every output pin compared after every
CLK edge, stopping at the first mismatch with the report ``tmc429 cosim`` gives, with the
functional coverage of ``tmc429 cosim --coverage``.

Run it as ``python -m tmc429.cocotb`` (:mod:`tmc429.cocotb.harness`); the test that runs inside
the simulator is :mod:`tmc429.cocotb.bench`; ports and port maps: :mod:`tmc429.cocotb.ports`.
Importing this package does not import cocotb.
"""
