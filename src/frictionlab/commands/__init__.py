"""Subcommands of the ``frictionlab`` command line, one module each."""
