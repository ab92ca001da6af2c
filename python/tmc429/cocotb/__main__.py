"""``python -m tmc429.cocotb``: see :mod:`tmc429.cocotb.harness`."""

import sys

from .harness import main

sys.exit(main())
