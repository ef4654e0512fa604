"""``python -m frictionlab.schema [--check]``: see :mod:`frictionlab.schema.generate`."""

import sys

from frictionlab.schema.generate import main

sys.exit(main())
