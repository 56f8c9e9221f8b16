"""dyncli — a command-line problem solver for engineering dynamics.

Kept import-light on purpose: ``dyncli --version`` must not import numpy.
"""

__version__ = "0.1.0"
