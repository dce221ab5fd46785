"""persson: contact mechanics of randomly rough surfaces from Python."""

from ._persson import version

__all__ = ["version"]
__version__ = version()
