"""AR errors carry a process exit code, so the CLI can `sys.exit(err.exit_code)`."""

from __future__ import annotations


class ARError(Exception):
    exit_code = 1


class PhotoUnreadable(ARError):
    """The photo/video cannot be opened or decoded (EX_NOINPUT)."""

    exit_code = 66


class NoMarkerFound(ARError):
    """No (or not the requested) ArUco marker in the image (EX_DATAERR)."""

    exit_code = 65


class AROptionError(ARError, ValueError):
    """A bad option value (usage error)."""

    exit_code = 2
