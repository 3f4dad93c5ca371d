"""cnlmc: the controlled-natural-language material compiler."""

__version__ = "0.1.0"
