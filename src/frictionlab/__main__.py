"""``python -m frictionlab`` runs the command-line interface."""

from frictionlab.cli import run

if __name__ == "__main__":
    run()
