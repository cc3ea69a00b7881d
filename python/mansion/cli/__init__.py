"""The ``mansion`` command line (typer); ``app`` is the console-script entry point."""

from mansion.cli.main import app

__all__ = ["app"]
