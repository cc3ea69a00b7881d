"""Access to the compiled Rust core, imported on first use.

Importing it lazily keeps ``import mansion`` (and the pure-Python models) usable while the
extension is not built, and turns a missing build into an error that says what to do.
"""

from __future__ import annotations

from types import ModuleType

__all__ = ["native"]


def native() -> ModuleType:
    """The ``mansion._core`` extension module."""
    try:
        from mansion import _core
    except ImportError as exc:
        raise ImportError(
            "mansion._core, the compiled Rust core of mansion, cannot be imported "
            f"({exc}). Install the package with `pip install .` (or `maturin develop`) "
            "from the repository root."
        ) from exc
    return _core
