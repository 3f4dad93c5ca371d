"""Exceptions that the CLI turns into messages and exit codes (never tracebacks)."""


class UsageError(Exception):
    """A problem with how cnlmc was called (exit 2)."""
