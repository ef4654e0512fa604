"""``python -m frictionlab`` runs the command-line interface."""

from frictionlab.cli import main

if __name__ == "__main__":
    raise SystemExit(main())
