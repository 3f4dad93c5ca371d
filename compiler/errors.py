"""Exceptions that the CLI turns into messages and exit codes (never tracebacks), and the codes."""

EXIT_OK, EXIT_ERRORS, EXIT_USAGE, EXIT_INTERNAL = 0, 1, 2, 70  # ok, errors in the input, usage, internal


class UsageError(Exception):
    """A problem with how cnlmc was called (exit 2)."""
